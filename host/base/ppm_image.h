// Netpbm colour images (PPM) as people hand them in: plain "P3" (numbers in text) or raw
// "P6" (bytes), any maximum value up to 65535.
#pragma once

#include "base/float_image.h"

#include <filesystem>
#include <string>

// The image with each sample divided by the file's maximum value (0..1). Throws
// std::runtime_error "PATH:LINE: REASON" for a header or a sample that is not what the
// format expects, and "PATH: REASON" for a file shorter than its header says; no pixel
// memory is reserved before the file is known to hold that many samples.
ImageF readPpm(const std::filesystem::path& path);

// The same for a file's bytes (PATH only names it in errors).
ImageF decodePpm(const std::filesystem::path& path, const std::string& bytes);
