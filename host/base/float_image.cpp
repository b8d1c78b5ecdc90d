// Formats by extension, the kernel's quantisation, and PFM files (the format is simple
// enough to write here: a text header, then raw floats).
#include "base/float_image.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw std::runtime_error(path.string() + ": " + reason);
}

std::string readFileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (file.bad()) fail(path, "cannot read");
    return bytes.str();
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// The header's fields: whitespace-separated tokens after the magic.
struct PfmHeaderReader {
    const std::filesystem::path& path;
    const std::string& bytes;
    std::size_t pos = 2;

    std::string_view token(const char* what) {
        while (pos < bytes.size() && isSpace(bytes[pos]))
            ++pos;
        const std::size_t start = pos;
        while (pos < bytes.size() && !isSpace(bytes[pos]) && pos - start < 32)
            ++pos;
        if (pos == start) fail(path, std::string("PFM header ends before its ") + what);
        return std::string_view(bytes).substr(start, pos - start);
    }
    template <typename T> T number(const char* what) {
        const std::string_view text = token(what);
        T value{};
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size())
            fail(path, std::string("PFM header: expected the ") + what + ", got '" +
                           printableText(text) + "'");
        return value;
    }
};

// Largest side read from a file: keeps a damaged header from asking for gigabytes.
constexpr int kMaxFileSide = 1 << 16;

void checkWritable(const std::filesystem::path& path, const ImageF& image) {
    if (image.width <= 0 || image.height <= 0)
        fail(path, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + ")");
    if (image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        fail(path, "image holds " + std::to_string(image.rgb.size()) + " floats, expected " +
                       std::to_string(image.width) + "x" + std::to_string(image.height) + "x3");
}

} // namespace

std::optional<ImageFormat> imageFormatOf(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".png") return ImageFormat::Png;
    if (extension == ".pfm") return ImageFormat::Pfm;
    if (extension == ".exr") return ImageFormat::Exr;
    return std::nullopt;
}

Image8 quantizeImage(const ImageF& image) {
    Image8 out;
    out.width = image.width;
    out.height = image.height;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    out.rgba.resize(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        for (std::size_t c = 0; c < 3; ++c) {
            // Float, as in the kernel: floor(sum / n * 255.0 + 0.5).
            const float level = std::floor(image.rgb[p * 3 + c] * 255.0f + 0.5f);
            out.rgba[p * 4 + c] = std::uint8_t(std::clamp(level, 0.0f, 255.0f));
        }
        out.rgba[p * 4 + 3] = 255;
    }
    return out;
}

ImageF imageFromBytes(const Image8& image) {
    ImageF out;
    out.width = image.width;
    out.height = image.height;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    out.rgb.resize(pixels * 3);
    for (std::size_t p = 0; p < pixels; ++p)
        for (std::size_t c = 0; c < 3; ++c)
            out.rgb[p * 3 + c] = float(image.rgba[p * 4 + c]);
    return out;
}

void writeFloatImage(const std::filesystem::path& path, const ImageF& image) {
    const std::optional<ImageFormat> format = imageFormatOf(path);
    if (format == ImageFormat::Pfm) return writePfm(path, image);
    if (format == ImageFormat::Exr) return writeExr(path, image);
    fail(path, std::string("not a float image file name (expected .pfm or .exr)"));
}

// "PF\n W H\n-1.0\n", then each row's RGB floats, little-endian, the bottom row first.
void writePfm(const std::filesystem::path& path, const ImageF& image) {
    checkWritable(path, image);
    const std::string header =
        "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    const std::size_t rowFloats = std::size_t(image.width) * 3;
    std::vector<std::uint8_t> bytes(header.begin(), header.end());
    bytes.reserve(header.size() + rowFloats * std::size_t(image.height) * 4);
    for (int y = image.height - 1; y >= 0; --y) {
        const float* row = &image.rgb[std::size_t(y) * rowFloats];
        for (std::size_t k = 0; k < rowFloats; ++k) {
            std::uint32_t bits = std::bit_cast<std::uint32_t>(row[k]);
            for (int b = 0; b < 4; ++b)
                bytes.push_back(std::uint8_t(bits >> (8 * b)));
        }
    }
    writeFileReplacing(path, bytes);
}

ImageF readPfm(const std::filesystem::path& path) {
    const std::string bytes = readFileBytes(path);
    if (bytes.size() < 3 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f') ||
        !isSpace(bytes[2]))
        fail(path, "not a PFM file (expected 'PF' or 'Pf' and a line break at the start)");
    const int channels = bytes[1] == 'F' ? 3 : 1;
    PfmHeaderReader header{path, bytes};
    const int width = header.number<int>("width");
    const int height = header.number<int>("height");
    const double scale = header.number<double>("scale (negative: little-endian)");
    if (width <= 0 || height <= 0 || width > kMaxFileSide || height > kMaxFileSide)
        fail(path, "PFM size " + std::to_string(width) + "x" + std::to_string(height) +
                       " is not 1.." + std::to_string(kMaxFileSide) + " a side");
    if (scale == 0 || !std::isfinite(scale)) fail(path, "PFM scale must be a non-zero number");
    // Exactly one whitespace byte separates the header from the pixels.
    if (header.pos >= bytes.size() || !isSpace(bytes[header.pos]))
        fail(path, "PFM header: expected a line break after the scale");
    const std::size_t dataStart = header.pos + 1;
    const std::size_t floats = std::size_t(width) * std::size_t(height) * std::size_t(channels);
    const std::size_t available = bytes.size() - dataStart;
    if (available < floats * 4)
        fail(path, "PFM pixels truncated: " + std::to_string(width) + "x" + std::to_string(height) +
                       "x" + std::to_string(channels) + " floats need " +
                       std::to_string(floats * 4) + " bytes, the file holds " +
                       std::to_string(available));
    const bool littleEndian = scale < 0;

    ImageF image;
    image.width = width;
    image.height = height;
    image.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
    const std::uint8_t* data = reinterpret_cast<const std::uint8_t*>(bytes.data()) + dataStart;
    for (int fileRow = 0; fileRow < height; ++fileRow) {
        const int y = height - 1 - fileRow; // the file's first row is the bottom one
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < channels; ++c) {
                const std::size_t k =
                    (std::size_t(fileRow) * std::size_t(width) + std::size_t(x)) * channels + c;
                std::uint32_t bits = 0;
                for (int b = 0; b < 4; ++b)
                    bits |= std::uint32_t(data[k * 4 + (littleEndian ? b : 3 - b)]) << (8 * b);
                const float value = std::bit_cast<float>(bits);
                if (!std::isfinite(value))
                    fail(path, "pixel (" + std::to_string(x) + "," + std::to_string(y) +
                                   ") holds a non-finite value");
                const std::size_t out = (std::size_t(y) * std::size_t(width) + x) * 3;
                for (int target = (channels == 1 ? 0 : c); target < (channels == 1 ? 3 : c + 1);
                     ++target)
                    image.rgb[out + std::size_t(target)] = value;
            }
        }
    }
    return image;
}
