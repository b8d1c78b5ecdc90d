#include "compare/jpeg_file.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>

namespace {

// The IJG (libjpeg) luminance table for quality 50, in the zig-zag order files store it.
constexpr std::array<int, 64> kStandardLuminance = {
    16, 11, 12,  14,  12,  10, 16, 14,  13,  14,  18,  17,  16, 19,  24,  40,
    26, 24, 22,  22,  24,  49, 35, 37,  29,  40,  58,  51,  61, 60,  57,  51,
    56, 55, 64,  72,  92,  78, 64, 68,  87,  69,  55,  56,  80, 109, 81,  87,
    95, 98, 103, 104, 103, 62, 77, 113, 121, 112, 100, 120, 92, 101, 103, 99};

// libjpeg's jpeg_quality_scaling and the table it makes from it (baseline: at most 255).
int scaledEntry(int standard, int quality) {
    const int scale = quality < 50 ? 5000 / quality : 200 - 2 * quality;
    return std::clamp((standard * scale + 50) / 100, 1, 255);
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw std::runtime_error(path.string() + ": " + reason);
}

} // namespace

JpegFacts readJpegFacts(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    JpegFacts facts;
    if (bytes.size() < 4 || bytes[0] != 0xFF || bytes[1] != 0xD8) fail(path, "not a JPEG file");
    std::optional<std::array<int, 64>> luminance;
    std::size_t at = 2;
    bool scanSeen = false;
    while (!scanSeen) {
        // Markers may be padded with extra 0xFF bytes.
        while (at < bytes.size() && bytes[at] == 0xFF && at + 1 < bytes.size() &&
               bytes[at + 1] == 0xFF)
            ++at;
        if (at + 4 > bytes.size() || bytes[at] != 0xFF)
            fail(path, "the file is cut short or damaged: no image data after " +
                           std::to_string(at) + " bytes");
        const int marker = bytes[at + 1];
        const std::size_t length = std::size_t(bytes[at + 2]) * 256 + bytes[at + 3];
        if (length < 2 || at + 2 + length > bytes.size())
            fail(path, "the file is cut short: a segment at byte " + std::to_string(at) +
                           " runs past its end");
        if (marker == 0xDB) { // define quantisation tables: precision and id, then 64 entries
            std::size_t table = at + 4;
            const std::size_t end = at + 2 + length;
            while (table < end) {
                const int precision = bytes[table] >> 4, id = bytes[table] & 15;
                const std::size_t size = precision ? 128 : 64;
                if (table + 1 + size > end) break;
                if (id == 0) {
                    std::array<int, 64> entries{};
                    for (std::size_t k = 0; k < 64; ++k)
                        entries[k] = precision
                                         ? bytes[table + 1 + 2 * k] * 256 + bytes[table + 2 + 2 * k]
                                         : bytes[table + 1 + k];
                    luminance = entries;
                }
                table += 1 + size;
            }
        }
        scanSeen = marker == 0xDA;
        at += 2 + length;
    }
    // Inside entropy-coded data a 0xFF byte is followed by 0x00 or a restart marker, so
    // the first 0xFF 0xD9 after the first scan is a marker: the end of the image.
    bool ended = false;
    for (std::size_t k = at; k + 1 < bytes.size() && !ended; ++k)
        ended = bytes[k] == 0xFF && bytes[k + 1] == 0xD9;
    if (!ended)
        fail(path, "the file is cut short: its image data has no end-of-image marker (" +
                       std::to_string(bytes.size()) + " bytes)");
    if (luminance) {
        long bestDistance = -1;
        for (int quality = 1; quality <= 100; ++quality) {
            long distance = 0;
            for (std::size_t k = 0; k < 64; ++k)
                distance +=
                    std::labs(long(scaledEntry(kStandardLuminance[k], quality)) - (*luminance)[k]);
            if (bestDistance < 0 || distance < bestDistance) {
                bestDistance = distance;
                facts.quality = quality;
            }
        }
        facts.exactTable = bestDistance == 0;
    }
    return facts;
}
