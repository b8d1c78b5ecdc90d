// What -o writes, by the file name's extension: the 8-bit image as PNG, JPEG or PPM, or the
// floats before the 8-bit rounding as PFM or OpenEXR; "-" is a PNG on stdout.
#pragma once

#include "base/float_image.h"
#include "base/image_io.h"

#include <filesystem>
#include <optional>

enum class OutputFormat { Png, Jpeg, Ppm, Pfm, Exr };

// By the extension, in any case (.png, .jpg, .jpeg, .ppm, .pfm, .exr); "-" is Png (to
// stdout); nullopt for any other name.
std::optional<OutputFormat> outputFormatOf(const std::filesystem::path& path);

// The names -o accepts, as its usage error lists them.
inline constexpr const char* kOutputNames =
    ".png, .jpg, .jpeg, .ppm, .pfm or .exr, or - for a PNG on stdout";

// -o -: the image goes to stdout, not to a file.
bool isStandardOutput(const std::filesystem::path& path);

// PFM and EXR hold floats; the others the 8-bit image.
bool holdsFloats(OutputFormat format);

inline constexpr int kDefaultJpegQuality = 90;

// path itself when nothing is there, else the first of STEM-1.EXT, STEM-2.EXT, ... that is
// free (the no-display fallback, which must not replace an earlier render).
std::filesystem::path firstUnusedName(const std::filesystem::path& path);

// Writes the 8-bit image in path's format (Png, Jpeg or Ppm): "PATH.tmp" renamed over PATH,
// as writePng does, or all to stdout for "-". Throws std::runtime_error "PATH: REASON".
void writeImage8(const std::filesystem::path& path, const Image8& image,
                 int jpegQuality = kDefaultJpegQuality);
