// The image a person hands in to be compared with the reference: PNG, JPEG, PPM (plain
// P3 or raw P6), PFM or OpenEXR, told apart by its first bytes rather than its name.
#pragma once

#include "base/float_image.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

enum class HandedInFormat { Png, Jpeg, Ppm, Pfm, Exr };

struct HandedInImage {
    // RGB in channel levels 0..255: 8-bit files as their bytes, PPM scaled from its maximum
    // value, float files times 255 (unclamped).
    ImageF levels;
    HandedInFormat format = HandedInFormat::Png;
    std::optional<int> jpegQuality;     // estimated from the file's quantisation table
    std::vector<std::uint8_t> jpegFile; // a JPEG's bytes: the reference is written like it
};

const char* formatName(HandedInFormat format); // "PNG", "JPEG", ...

// Whether the format stores colours exactly (not JPEG).
inline bool isExactFormat(HandedInFormat format) {
    return format != HandedInFormat::Jpeg;
}

// Throws std::runtime_error "PATH: REASON" (with ":LINE" for a plain PPM) when the file
// cannot be opened, is empty, is none of these formats, is cut short or damaged, or states
// a size over 16384 pixels a side; a header's size is checked before pixels are decoded.
HandedInImage readHandedInImage(const std::filesystem::path& path);
