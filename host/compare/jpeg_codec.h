// JPEG through libjpeg (libjpeg-turbo): the library most JPEG files people hand in were
// written with (PIL, OpenCV, ImageMagick, GIMP). compare decodes a JPEG here, and writes
// the reference as that file was written, with its quantisation tables and chroma
// sampling, so that the two carry the same kind of compression errors.
#pragma once

#include "base/float_image.h"

#include <cstdint>
#include <filesystem>
#include <vector>

// The image in levels 0..255. Throws std::runtime_error "PATH: REASON" for a file libjpeg
// cannot read, one it reads only with a warning (cut short, damaged data), or one over
// maxSide pixels a side (checked from the header, before the pixels are decoded).
ImageF decodeJpeg(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes,
                  int maxSide);

// levels (0..255, rounded and clamped to bytes) encoded with the quantisation tables and
// sampling factors of the JPEG file original, then decoded as decodeJpeg does.
ImageF throughJpegLike(const ImageF& levels, const std::vector<std::uint8_t>& original);

// levels encoded by libjpeg at quality 1..100 with its defaults (4:2:0 chroma), as most
// programs write a JPEG; for tests and tools.
std::vector<std::uint8_t> encodeJpegWithLibjpeg(const ImageF& levels, int quality);
