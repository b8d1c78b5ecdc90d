#include "base/image_io.h"

#include <cerrno>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>
#include <utility>

// stb is third-party code written for C; its warnings are not ours to fix.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
// Static, so no other file that happens to compile stb clashes with ours.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_PNM
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw std::runtime_error(path.string() + ": " + reason);
}

} // namespace

Image8 readPng(const std::filesystem::path& path) {
    // stb's own fopen would report only "can't fopen"; opening here keeps errno.
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_file(file.get(), &width, &height, &channels, 4), &stbi_image_free);
    if (!pixels) fail(path, std::string("not a readable PNG: ") + stbi_failure_reason());
    Image8 image;
    image.width = width;
    image.height = height;
    const std::size_t bytes = std::size_t(width) * std::size_t(height) * 4;
    image.rgba.assign(pixels.get(), pixels.get() + bytes);
    return image;
}

namespace {

void checkImage(const std::filesystem::path& path, const Image8& image) {
    if (image.width <= 0 || image.height <= 0)
        fail(path, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + ")");
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        fail(path, "image holds " + std::to_string(image.rgba.size()) + " bytes, expected " +
                       std::to_string(image.width) + "x" + std::to_string(image.height) + "x4");
    if (image.width > std::numeric_limits<int>::max() / 4) fail(path, "image too wide to encode");
}

// stb's encoders write through this into memory: stbi_write_* ignore fwrite and fclose
// errors, so a full disk would pass unnoticed; writeFileReplacing checks every step.
void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

} // namespace

Image8 readImage8(const std::filesystem::path& path) {
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_file(file.get(), &width, &height, &channels, 4), &stbi_image_free);
    if (!pixels)
        fail(path, std::string("not a readable PNG, JPEG or PPM: ") + stbi_failure_reason());
    Image8 image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels.get(), pixels.get() + std::size_t(width) * std::size_t(height) * 4);
    return image;
}

namespace {

// A PNG's size as its header states it: stb refuses a PNG over 2^30 bytes of pixels with
// the same words as a file of no known type, which would hide why.
std::optional<std::pair<std::uint32_t, std::uint32_t>>
pngHeaderSize(const std::vector<std::uint8_t>& bytes) {
    static const std::uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 24 || std::memcmp(bytes.data(), signature, 8) != 0 ||
        std::memcmp(bytes.data() + 12, "IHDR", 4) != 0)
        return std::nullopt;
    auto bigEndian = [&](std::size_t at) {
        return std::uint32_t(bytes[at]) << 24 | std::uint32_t(bytes[at + 1]) << 16 |
               std::uint32_t(bytes[at + 2]) << 8 | std::uint32_t(bytes[at + 3]);
    };
    return std::pair(bigEndian(16), bigEndian(20));
}

} // namespace

Image8 decodeImage8(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                    int maxSide) {
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
        fail(path, "the file is too large to decode");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = int(bytes.size());
    int width = 0, height = 0, channels = 0;
    const auto tooLarge = [&](std::uint64_t w, std::uint64_t h) {
        fail(path, "the image is " + std::to_string(w) + "x" + std::to_string(h) + ", over " +
                       std::to_string(maxSide) + " pixels a side");
    };
    // stb is built with its PNM reader (readImage8 reads the PPM files this project writes),
    // which reads past the end of a cut-short 16-bit PPM (found by the fuzz run): a decoded
    // file is never given to it.
    if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7')
        fail(path, "not a readable PNG, JPEG, BMP or TGA image: a PNM (PPM, PGM) file");
    if (const auto stated = pngHeaderSize(bytes);
        stated &&
        (stated->first > std::uint32_t(maxSide) || stated->second > std::uint32_t(maxSide)))
        tooLarge(stated->first, stated->second);
    if (!stbi_info_from_memory(data, size, &width, &height, &channels))
        fail(path,
             std::string("not a readable PNG, JPEG, BMP or TGA image: ") + stbi_failure_reason());
    if (width > maxSide || height > maxSide) tooLarge(width, height);
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(data, size, &width, &height, &channels, 4), &stbi_image_free);
    if (!pixels)
        fail(path,
             std::string("not a readable PNG, JPEG, BMP or TGA image: ") + stbi_failure_reason());
    Image8 image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels.get(), pixels.get() + std::size_t(width) * std::size_t(height) * 4);
    return image;
}

std::vector<std::uint8_t> encodePng(const std::filesystem::path& path, const Image8& image) {
    checkImage(path, image);
    std::vector<std::uint8_t> encoded;
    // The "Sub" filter on every row, instead of stb's per-row trial of all five: on
    // rendered images it encodes about a third faster and a few percent smaller
    // (measured on test2 and showcase at 640x480), and encoding is part of start-up.
    stbi_write_force_png_filter = 1;
    if (!stbi_write_png_to_func(appendBytes, &encoded, image.width, image.height, 4,
                                image.rgba.data(), image.width * 4))
        fail(path, "PNG encoder failed");
    return encoded;
}

std::vector<std::uint8_t> encodeJpeg(const std::filesystem::path& path, const Image8& image,
                                     int quality) {
    checkImage(path, image);
    // JPEG has no alpha: stb drops the fourth channel of each pixel (always 255 here).
    std::vector<std::uint8_t> encoded;
    if (!stbi_write_jpg_to_func(appendBytes, &encoded, image.width, image.height, 4,
                                image.rgba.data(), quality))
        fail(path, "JPEG encoder failed");
    return encoded;
}

std::vector<std::uint8_t> encodePpm(const std::filesystem::path& path, const Image8& image) {
    checkImage(path, image);
    const std::string header =
        "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
    std::vector<std::uint8_t> encoded(header.begin(), header.end());
    encoded.reserve(header.size() + image.rgba.size() / 4 * 3);
    for (std::size_t p = 0; p < image.rgba.size(); p += 4)
        encoded.insert(encoded.end(), image.rgba.begin() + std::ptrdiff_t(p),
                       image.rgba.begin() + std::ptrdiff_t(p + 3));
    return encoded;
}

void writePng(const std::filesystem::path& path, const Image8& image) {
    writeFileReplacing(path, encodePng(path, image));
}

void writeStandardOutput(const std::vector<std::uint8_t>& bytes) {
    std::fflush(stdout); // nothing else is written there, but keep the order if it were
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t step = ::write(STDOUT_FILENO, bytes.data() + written, bytes.size() - written);
        if (step < 0 && errno == EINTR) continue;
        if (step <= 0)
            throw std::runtime_error(std::string("cannot write the image to stdout: ") +
                                     std::strerror(errno));
        written += std::size_t(step);
    }
}

void writeFileReplacing(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) fail(path, "cannot create " + temporary.string() + ": " + std::strerror(errno));
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    int error = errno;
    const bool closed = std::fclose(file) == 0;
    if (written && !closed) error = errno;
    if (!written || !closed) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, "cannot write " + temporary.string() + ": " + std::strerror(error));
    }
    std::error_code renameError;
    std::filesystem::rename(temporary, path, renameError);
    if (renameError) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(path, "cannot replace with the written file: " + renameError.message());
    }
}

void reservePngOutput(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) fail(path, "is a folder, not a file name");
    // Named as such, rather than as a failure to create PATH.tmp, which the user never named.
    const std::filesystem::path folder = path.parent_path();
    if (!folder.empty() && !std::filesystem::exists(folder, error))
        fail(path, "the folder " + folder.string() + " does not exist");
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) fail(path, "cannot create " + temporary.string() + ": " + std::strerror(errno));
    std::fclose(file);
}

void releasePngOutput(const std::filesystem::path& path) {
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
}
