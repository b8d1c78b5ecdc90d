#include "compare/float_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

FloatComparison compareFloatImages(const ImageF& a, const ImageF& b, double tolerance) {
    for (const ImageF* image : {&a, &b})
        if (image->width < 0 || image->height < 0 ||
            image->rgb.size() != std::size_t(image->width) * std::size_t(image->height) * 3)
            throw std::invalid_argument("float image buffer of " +
                                        std::to_string(image->rgb.size()) +
                                        " values does not match its size");
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("image sizes differ: " + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " vs " + std::to_string(b.width) +
                                    "x" + std::to_string(b.height));
    FloatComparison result;
    result.tolerance = tolerance;
    result.pixels = long(a.width) * long(a.height);
    double squares = 0;
    for (std::size_t p = 0; p < std::size_t(result.pixels); ++p) {
        double worst = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgb[p * 3 + c]) - double(b.rgb[p * 3 + c]);
            squares += d * d;
            worst = std::max(worst, std::abs(d));
        }
        if (worst <= tolerance) ++result.pixelsWithinTolerance;
        if (worst > result.maxAbsoluteError) {
            result.maxAbsoluteError = worst;
            result.worstX = int(p % std::size_t(a.width));
            result.worstY = int(p / std::size_t(a.width));
        }
    }
    if (result.pixels > 0) result.rmse = std::sqrt(squares / (3.0 * double(result.pixels)));
    return result;
}

std::string describe(const FloatComparison& comparison) {
    char text[256];
    if (comparison.pixelsWithinTolerance == comparison.pixels) {
        std::snprintf(text, sizeof text, "float: 100%% of %ld pixels", comparison.pixels);
    } else {
        // Rounded down, so "100%" is printed only when every pixel matches.
        const double fraction =
            double(comparison.pixelsWithinTolerance) / double(std::max(comparison.pixels, 1L));
        std::snprintf(text, sizeof text, "float: %.2f%% of %ld pixels",
                      std::floor(fraction * 10000.0) / 100.0, comparison.pixels);
    }
    std::string result = text;
    std::snprintf(text, sizeof text, " within %g, max abs error %.4g at (%d,%d), RMSE %.4g",
                  comparison.tolerance, comparison.maxAbsoluteError, comparison.worstX,
                  comparison.worstY, comparison.rmse);
    return result + text;
}
