// OpenEXR files through tinyexr (Debian: libtinyexr-dev): 32-bit float R, G, B channels,
// lossless ZIP compression, encoded to memory so that the write itself is checked and
// atomic (writeFileReplacing), and decoded from memory for the same reason.
#include "base/float_image.h"

#include <tinyexr.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw std::runtime_error(path.string() + ": " + reason);
}

// tinyexr's message (which it allocates), or a fallback.
std::string takeMessage(const char* message, const char* fallback) {
    if (!message) return fallback;
    std::string text = printableText(message); // it may quote the damaged file
    FreeEXRErrorMessage(message);
    return text;
}

} // namespace

void writeExr(const std::filesystem::path& path, const ImageF& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        fail(path, "cannot write an empty or inconsistent " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " image");
    // Channels in the alphabetical order that EXR readers expect: B, G, R, one plane each.
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<float> planes[3];
    for (int c = 0; c < 3; ++c) {
        planes[c].resize(pixels);
        for (std::size_t p = 0; p < pixels; ++p)
            planes[c][p] = image.rgb[p * 3 + std::size_t(2 - c)];
    }
    float* planePointers[3] = {planes[0].data(), planes[1].data(), planes[2].data()};

    EXRImage exrImage;
    InitEXRImage(&exrImage);
    exrImage.num_channels = 3;
    exrImage.images = reinterpret_cast<unsigned char**>(planePointers);
    exrImage.width = image.width;
    exrImage.height = image.height;

    EXRHeader header;
    InitEXRHeader(&header);
    EXRChannelInfo channels[3] = {};
    std::strcpy(channels[0].name, "B");
    std::strcpy(channels[1].name, "G");
    std::strcpy(channels[2].name, "R");
    int pixelTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = pixelTypes;
    header.requested_pixel_types = pixelTypes; // stored as given: 32-bit float
    // tinyexr's own SaveEXR leaves images under 16x16 uncompressed; so do we.
    header.compression_type = image.width < 16 && image.height < 16 ? TINYEXR_COMPRESSIONTYPE_NONE
                                                                    : TINYEXR_COMPRESSIONTYPE_ZIP;

    unsigned char* memory = nullptr;
    const char* message = nullptr;
    const std::size_t size = SaveEXRImageToMemory(&exrImage, &header, &memory, &message);
    std::unique_ptr<unsigned char, void (*)(void*)> encoded(memory, &std::free);
    if (size == 0 || !memory)
        fail(path, "EXR encoder failed: " + takeMessage(message, "no reason"));
    writeFileReplacing(path, std::vector<std::uint8_t>(memory, memory + size));
}

ImageF readExr(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream stream;
    stream << file.rdbuf();
    const std::string bytes = stream.str();
    // The magic first, so a file that is not EXR at all gets a plain answer.
    if (bytes.size() < 4 || std::memcmp(bytes.data(), "\x76\x2f\x31\x01", 4) != 0)
        fail(path, "not an OpenEXR file (expected the magic number 76 2f 31 01)");

    float* rgba = nullptr;
    int width = 0, height = 0;
    const char* message = nullptr;
    const int status = LoadEXRFromMemory(&rgba, &width, &height,
                                         reinterpret_cast<const unsigned char*>(bytes.data()),
                                         bytes.size(), &message);
    std::unique_ptr<float, void (*)(void*)> pixels(rgba, &std::free);
    if (status != TINYEXR_SUCCESS || !rgba)
        fail(path, "not a readable OpenEXR image: " + takeMessage(message, "no reason given"));
    if (width <= 0 || height <= 0) fail(path, "OpenEXR image has no pixels");

    ImageF image;
    image.width = width;
    image.height = height;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    image.rgb.resize(count * 3);
    for (std::size_t p = 0; p < count; ++p) {
        for (std::size_t c = 0; c < 3; ++c) {
            const float value = rgba[p * 4 + c];
            if (!std::isfinite(value))
                fail(path, "pixel (" + std::to_string(p % std::size_t(width)) + "," +
                               std::to_string(p / std::size_t(width)) +
                               ") holds a non-finite value");
            image.rgb[p * 3 + c] = value;
        }
    }
    return image;
}
