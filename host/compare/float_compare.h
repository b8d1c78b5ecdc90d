// Per-pixel comparison of two float images (PFM or EXR: the averages before the 8-bit
// rounding), for image_diff and the tests: below the 8-bit floor, where compareImages
// (image_compare.h) sees only whole levels.
#pragma once

#include "base/float_image.h"

#include <string>

struct FloatComparison {
    long pixels = 0;
    double tolerance = 0;           // the largest channel difference that still matches
    long pixelsWithinTolerance = 0; // every RGB channel differs by <= tolerance
    double maxAbsoluteError = 0;    // over all pixels and RGB channels
    int worstX = 0, worstY = 0;     // first pixel (row-major) with that error
    double rmse = 0;                // over all pixels and RGB channels, in the images' units
};

// Throws std::invalid_argument if the sizes differ or a buffer does not match its size.
FloatComparison compareFloatImages(const ImageF& a, const ImageF& b, double tolerance);

// "float: 99.87% of 19200 pixels within 1e-05, max abs error 3.052e-05 at (10,20), RMSE 1.2e-06"
std::string describe(const FloatComparison& comparison);
