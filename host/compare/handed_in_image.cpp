#include "compare/handed_in_image.h"

#include "base/image_io.h"
#include "base/ppm_image.h"
#include "compare/jpeg_codec.h"
#include "compare/jpeg_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr int kMaxSide = 16384;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw std::runtime_error(path.string() + ": " + reason);
}

std::vector<std::uint8_t> fileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                    std::istreambuf_iterator<char>());
    if (file.bad()) fail(path, std::string("cannot read: ") + std::strerror(errno));
    return bytes;
}

bool startsWith(const std::vector<std::uint8_t>& bytes, std::initializer_list<int> magic) {
    if (bytes.size() < magic.size()) return false;
    std::size_t k = 0;
    for (int byte : magic)
        if (bytes[k++] != byte) return false;
    return true;
}

ImageF timesLevels(ImageF image) {
    for (float& value : image.rgb)
        value *= 255.0f;
    return image;
}

} // namespace

const char* formatName(HandedInFormat format) {
    switch (format) {
    case HandedInFormat::Png:
        return "PNG";
    case HandedInFormat::Jpeg:
        return "JPEG";
    case HandedInFormat::Ppm:
        return "PPM";
    case HandedInFormat::Pfm:
        return "PFM";
    case HandedInFormat::Exr:
        return "OpenEXR";
    }
    return "?";
}

HandedInImage readHandedInImage(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) fail(path, "is a folder, not an image");
    const std::vector<std::uint8_t> bytes = fileBytes(path);
    if (bytes.empty()) fail(path, "the file is empty");
    HandedInImage image;
    if (startsWith(bytes, {0x89, 'P', 'N', 'G'})) {
        image.format = HandedInFormat::Png;
        image.levels = imageFromBytes(decodeImage8(path, bytes, kMaxSide));
    } else if (startsWith(bytes, {0xFF, 0xD8})) {
        image.format = HandedInFormat::Jpeg;
        image.jpegQuality = readJpegFacts(path, bytes).quality;
        image.levels = decodeJpeg(path, bytes, kMaxSide);
        image.jpegFile = bytes;
    } else if (startsWith(bytes, {'P', '3'}) || startsWith(bytes, {'P', '6'})) {
        image.format = HandedInFormat::Ppm;
        image.levels = timesLevels(readPpm(path));
    } else if (startsWith(bytes, {'P', 'F'}) || startsWith(bytes, {'P', 'f'})) {
        image.format = HandedInFormat::Pfm;
        image.levels = timesLevels(readPfm(path));
    } else if (startsWith(bytes, {0x76, 0x2F, 0x31, 0x01})) {
        image.format = HandedInFormat::Exr;
        image.levels = timesLevels(readExr(path));
    } else {
        fail(path, "not an image compare reads: expected PNG, JPEG, PPM (P3 or P6), PFM or "
                   "OpenEXR, by the file's first bytes");
    }
    if (image.levels.width > kMaxSide || image.levels.height > kMaxSide)
        fail(path, "the image is " + std::to_string(image.levels.width) + "x" +
                       std::to_string(image.levels.height) + ", over the " +
                       std::to_string(kMaxSide) + " pixels a side compare reads");
    return image;
}
