// Float RGB images: each pixel's average of clamped samples before the 8-bit rounding, and
// the files that hold them (PFM and OpenEXR), chosen with PNG by the file's extension. No
// Vulkan, so the reference renderer, image_diff and the tests use it without a GPU.
#pragma once

#include "base/image_io.h"
#include "base/printable_text.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Row-major, top row first, 3 floats per pixel (R, G, B).
struct ImageF {
    int width = 0, height = 0;
    std::vector<float> rgb;
};

enum class ImageFormat { Png, Pfm, Exr };

// The format an output or input file name asks for, by its extension (.png, .pfm, .exr,
// in any case); nullopt for any other.
std::optional<ImageFormat> imageFormatOf(const std::filesystem::path& path);

// The extensions -o accepts, as usage errors name them.
inline constexpr const char* kKnownImageExtensions = ".png, .pfm or .exr";

// The 8-bit image the kernel writes for these floats: floor(c * 255 + 0.5) in float
// arithmetic, as shaders/trace.comp does, clamped to 0..255; alpha 255.
Image8 quantizeImage(const ImageF& image);

// The bytes as floats 0..255 (for measures that work on floats, such as SSIM).
ImageF imageFromBytes(const Image8& image);

// Writes "PATH.tmp" and renames it over PATH, as writePng does; the format follows the
// extension (PFM: little-endian RGB floats, rows bottom to top; EXR: 32-bit float R, G, B,
// ZIP-compressed, through tinyexr). Throws std::runtime_error "PATH: REASON".
void writeFloatImage(const std::filesystem::path& path, const ImageF& image);
void writePfm(const std::filesystem::path& path, const ImageF& image);
void writeExr(const std::filesystem::path& path, const ImageF& image);

// Reads a PFM (colour "PF" or grey "Pf", either byte order) or a single-part scanline
// OpenEXR file with half or float R, G and B channels (others are ignored). Throws
// std::runtime_error "PATH: REASON" for anything else: a wrong magic, a damaged or truncated header
// or pixel block, a non-finite value.
ImageF readPfm(const std::filesystem::path& path);
ImageF readExr(const std::filesystem::path& path);
