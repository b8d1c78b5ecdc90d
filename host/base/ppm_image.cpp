#include "base/ppm_image.h"

#include "base/printable_text.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace {

// The file's bytes with a cursor and the line it is on, for the header and plain samples.
struct PpmText {
    const std::filesystem::path& path;
    const std::string& bytes;
    std::size_t at = 0;
    int line = 1;

    [[noreturn]] void fail(const std::string& reason) const {
        throw std::runtime_error(path.string() + ":" + std::to_string(line) + ": " + reason);
    }

    // Skips whitespace and # comments (to the end of their line).
    void skipSpace() {
        while (at < bytes.size()) {
            const char c = bytes[at];
            if (c == '#') {
                while (at < bytes.size() && bytes[at] != '\n')
                    ++at;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f') {
                if (c == '\n') ++line;
                ++at;
            } else {
                return;
            }
        }
    }

    // The next whole number, what it is named in an error; at most limit.
    long number(const char* what, long limit) {
        skipSpace();
        if (at >= bytes.size()) fail(std::string("expected ") + what + ", but the file ends");
        const std::size_t start = at;
        long value = 0;
        while (at < bytes.size() && bytes[at] >= '0' && bytes[at] <= '9') {
            value = value * 10 + (bytes[at] - '0');
            if (value > limit)
                fail(std::string("expected ") + what + " of at most " + std::to_string(limit));
            ++at;
        }
        if (at == start || (at < bytes.size() && !std::strchr(" \t\r\n\v\f#", bytes[at])))
            fail(std::string("expected ") + what + ", got '" +
                 printableText(
                     bytes.substr(start, std::min<std::size_t>(12, bytes.size() - start))) +
                 "'");
        return value;
    }
};

// Sizes a file may state: each side at most 65536, and no more than 2^28 pixels.
constexpr long kMaxSide = 65536;
constexpr std::size_t kMaxPixels = std::size_t(1) << 28;

} // namespace

ImageF readPpm(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error(path.string() + ": cannot open: " + std::strerror(errno));
    const std::string bytes((std::istreambuf_iterator<char>(file)),
                            std::istreambuf_iterator<char>());
    if (file.bad())
        throw std::runtime_error(path.string() + ": cannot read: " + std::strerror(errno));
    return decodePpm(path, bytes);
}

ImageF decodePpm(const std::filesystem::path& path, const std::string& bytes) {
    PpmText text{path, bytes};
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '3' && bytes[1] != '6'))
        text.fail("not a colour PPM: expected \"P3\" or \"P6\" at the start");
    const bool plain = bytes[1] == '3';
    text.at = 2;
    ImageF image;
    image.width = int(text.number("the width", kMaxSide));
    image.height = int(text.number("the height", kMaxSide));
    if (image.width == 0 || image.height == 0) text.fail("the image has no pixels");
    const long maximum = text.number("the maximum value (1 to 65535)", 65535);
    if (maximum == 0) text.fail("expected the maximum value (1 to 65535), got 0");
    const std::size_t samples = std::size_t(image.width) * std::size_t(image.height) * 3;
    if (samples / 3 > kMaxPixels) text.fail("the image is too large to compare");
    const std::size_t bytesPerSample = maximum > 255 ? 2 : 1;
    if (plain) {
        // Each plain sample takes at least a digit and a separator.
        if (samples > (bytes.size() - text.at + 1) / 2)
            throw std::runtime_error(
                path.string() + ": the header says " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " pixels, but the file is too short to hold them");
        image.rgb.resize(samples);
        for (float& sample : image.rgb)
            sample = float(text.number("a sample value", maximum)) / float(maximum);
        return image;
    }
    // Exactly one whitespace byte ends a raw file's header.
    ++text.at;
    if (bytes.size() < text.at || (bytes.size() - text.at) / bytesPerSample < samples)
        throw std::runtime_error(path.string() + ": the header says " +
                                 std::to_string(image.width) + "x" + std::to_string(image.height) +
                                 " pixels, but the file ends after " +
                                 std::to_string(bytes.size() - std::min(bytes.size(), text.at)) +
                                 " bytes of them, not " + std::to_string(samples * bytesPerSample));
    image.rgb.resize(samples);
    const auto* raw = reinterpret_cast<const unsigned char*>(bytes.data() + text.at);
    for (std::size_t k = 0; k < samples; ++k) {
        const long value = bytesPerSample == 2 ? raw[2 * k] * 256L + raw[2 * k + 1] : raw[k];
        if (value > maximum)
            throw std::runtime_error(path.string() + ": sample " + std::to_string(k) + " is " +
                                     std::to_string(value) + ", above the maximum value " +
                                     std::to_string(maximum));
        image.rgb[k] = float(value) / float(maximum);
    }
    return image;
}
