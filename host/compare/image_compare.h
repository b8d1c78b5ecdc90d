// Per-pixel comparison of two 8-bit images: a metric, a tolerance and a diff
// image, for the tests and the image_diff tool. Alpha is ignored (RGB only).
#pragma once

#include "base/image_io.h"

#include <string>

struct ImageComparison {
    int width = 0, height = 0;
    int tolerance = 0; // the largest channel difference that still matches
    long pixels = 0;
    long pixelsWithinTolerance = 0; // every RGB channel differs by <= tolerance
    double fractionWithinTolerance = 0;
    int maxChannelDifference = 0; // over all pixels and RGB channels, 0..255
    double rmse = 0;              // in 0..255 units over all RGB channels
    int worstX = 0, worstY = 0;   // first pixel (row-major) with the max difference
};

// Throws std::invalid_argument if the sizes differ or an image's buffer does not
// match its size.
ImageComparison compareImages(const Image8& a, const Image8& b, int tolerance);

// A dim grey copy of a; pixels over tolerance are red, brighter the larger the
// difference, so that a few stray pixels are easy to spot.
Image8 diffImage(const Image8& a, const Image8& b, int tolerance);

// "99.87% of 19200 pixels within 2/255, max diff 7/255 at (10,20), RMSE 0.31"
std::string describe(const ImageComparison& comparison);
