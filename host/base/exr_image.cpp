// OpenEXR files through tinyexr (Debian: libtinyexr-dev): 32-bit float R, G, B channels,
// lossless ZIP compression, encoded to memory so that the write itself is checked and
// atomic (writeFileReplacing), and decoded from memory for the same reason.
#include "base/float_image.h"
#include "base/scope_guard.h"

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
    std::string text = message;
    FreeEXRErrorMessage(message);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();        // its messages end in a line break
    return printableText(text); // they may quote the damaged file
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
    const auto* memory = reinterpret_cast<const unsigned char*>(bytes.data());

    // tinyexr's own LoadEXRFromMemory leaks the header when the pixels fail to decode
    // (LeakSanitizer saw it on truncated files): here the header and the image are
    // released on every path.
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, memory, bytes.size()) != TINYEXR_SUCCESS)
        fail(path, "not a readable OpenEXR image: damaged version field");
    if (version.multipart || version.non_image)
        fail(path, "not a readable OpenEXR image: multi-part and deep files are not read");
    EXRHeader header;
    InitEXRHeader(&header);
    ScopeExit releaseHeader([&] { FreeEXRHeader(&header); });
    const char* message = nullptr;
    if (ParseEXRHeaderFromMemory(&header, &version, memory, bytes.size(), &message) !=
        TINYEXR_SUCCESS)
        fail(path, "not a readable OpenEXR image: " + takeMessage(message, "damaged header"));
    if (header.tiled) fail(path, "not a readable OpenEXR image: tiled files are not read");
    int channelOf[3] = {-1, -1, -1}; // R, G, B
    for (int c = 0; c < header.num_channels; ++c) {
        const char* name = header.channels[c].name;
        for (int k = 0; k < 3; ++k)
            if (name[0] == "RGB"[k] && name[1] == '\0') channelOf[k] = c;
        if (header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF)
            header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT; // decoded as float
    }
    for (int k = 0; k < 3; ++k) {
        if (channelOf[k] < 0)
            fail(path, std::string("not a readable OpenEXR image: no ") + "RGB"[k] + " channel");
        if (header.requested_pixel_types[channelOf[k]] != TINYEXR_PIXELTYPE_FLOAT)
            fail(path, std::string("not a readable OpenEXR image: channel ") + "RGB"[k] +
                           " is not half or float");
    }
    EXRImage exrImage;
    InitEXRImage(&exrImage);
    // A failed load has released what it allocated (freeing it again would be a double
    // free, AddressSanitizer found), so the image is released only once it has loaded.
    if (LoadEXRImageFromMemory(&exrImage, &header, memory, bytes.size(), &message) !=
        TINYEXR_SUCCESS)
        fail(path, "not a readable OpenEXR image: " + takeMessage(message, "damaged pixels"));
    ScopeExit releaseImage([&] { FreeEXRImage(&exrImage); });
    if (exrImage.width <= 0 || exrImage.height <= 0 || !exrImage.images)
        fail(path, "OpenEXR image has no pixels");

    ImageF image;
    image.width = exrImage.width;
    image.height = exrImage.height;
    const std::size_t count = std::size_t(image.width) * std::size_t(image.height);
    image.rgb.resize(count * 3);
    for (std::size_t k = 0; k < 3; ++k) {
        const auto* plane = reinterpret_cast<const float*>(exrImage.images[channelOf[k]]);
        for (std::size_t p = 0; p < count; ++p) {
            if (!std::isfinite(plane[p]))
                fail(path, "pixel (" + std::to_string(p % std::size_t(image.width)) + "," +
                               std::to_string(p / std::size_t(image.width)) +
                               ") holds a non-finite value");
            image.rgb[p * 3 + k] = plane[p];
        }
    }
    return image;
}
