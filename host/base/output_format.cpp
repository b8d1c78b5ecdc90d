#include "base/output_format.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

std::optional<OutputFormat> outputFormatOf(const std::filesystem::path& path) {
    if (isStandardOutput(path)) return OutputFormat::Png;
    if (!path.has_stem()) return std::nullopt;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png") return OutputFormat::Png;
    if (extension == ".jpg" || extension == ".jpeg") return OutputFormat::Jpeg;
    if (extension == ".ppm") return OutputFormat::Ppm;
    if (extension == ".pfm") return OutputFormat::Pfm;
    if (extension == ".exr") return OutputFormat::Exr;
    return std::nullopt;
}

bool isStandardOutput(const std::filesystem::path& path) {
    return path == "-";
}

bool holdsFloats(OutputFormat format) {
    return format == OutputFormat::Pfm || format == OutputFormat::Exr;
}

void writeImage8(const std::filesystem::path& path, const Image8& image, int jpegQuality) {
    if (isStandardOutput(path)) return writeStandardOutput(encodePng("stdout", image));
    const std::optional<OutputFormat> format = outputFormatOf(path);
    if (format == OutputFormat::Png) return writeFileReplacing(path, encodePng(path, image));
    if (format == OutputFormat::Jpeg)
        return writeFileReplacing(path, encodeJpeg(path, image, jpegQuality));
    if (format == OutputFormat::Ppm) return writeFileReplacing(path, encodePpm(path, image));
    throw std::logic_error(path.string() + ": not an 8-bit image format");
}

std::filesystem::path firstUnusedName(const std::filesystem::path& path) {
    constexpr unsigned kMostTries = 100000;
    for (unsigned n = 0; n < kMostTries; ++n) {
        std::filesystem::path candidate = path;
        if (n > 0)
            candidate.replace_filename(path.stem().string() + "-" + std::to_string(n) +
                                       path.extension().string());
        std::error_code error; // set only when the answer is unknown, not for "absent"
        if (!std::filesystem::exists(candidate, error)) {
            if (error) throw std::runtime_error(candidate.string() + ": " + error.message());
            return candidate;
        }
    }
    throw std::runtime_error(path.string() + " and " + std::to_string(kMostTries - 1) +
                             " numbered names after it all exist");
}
