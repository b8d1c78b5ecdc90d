#include "compare/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace {

std::string sizeText(const Image8& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void checkComparable(const Image8& a, const Image8& b) {
    for (const Image8* image : {&a, &b})
        if (image->width < 0 || image->height < 0 ||
            image->rgba.size() != std::size_t(image->width) * std::size_t(image->height) * 4)
            throw std::invalid_argument("image buffer of " + std::to_string(image->rgba.size()) +
                                        " bytes does not match its size " + sizeText(*image));
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("image sizes differ: " + sizeText(a) + " vs " + sizeText(b));
}

// The largest RGB channel difference of pixel p.
int pixelDifference(const Image8& a, const Image8& b, std::size_t p) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(a.rgba[p * 4 + c]) - int(b.rgba[p * 4 + c])));
    return worst;
}

} // namespace

ImageComparison compareImages(const Image8& a, const Image8& b, int tolerance) {
    checkComparable(a, b);
    ImageComparison result;
    result.width = a.width;
    result.height = a.height;
    result.tolerance = tolerance;
    result.pixels = long(a.width) * long(a.height);
    double squares = 0;
    for (std::size_t p = 0; p < std::size_t(result.pixels); ++p) {
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[p * 4 + c]) - double(b.rgba[p * 4 + c]);
            squares += d * d;
        }
        const int difference = pixelDifference(a, b, p);
        if (difference <= tolerance) ++result.pixelsWithinTolerance;
        if (difference > result.maxChannelDifference) {
            result.maxChannelDifference = difference;
            result.worstX = int(p % std::size_t(a.width));
            result.worstY = int(p / std::size_t(a.width));
        }
    }
    if (result.pixels > 0) {
        result.fractionWithinTolerance =
            double(result.pixelsWithinTolerance) / double(result.pixels);
        result.rmse = std::sqrt(squares / (3.0 * double(result.pixels)));
    } else {
        result.fractionWithinTolerance = 1.0; // nothing differs in an empty image
    }
    return result;
}

Image8 diffImage(const Image8& a, const Image8& b, int tolerance) {
    checkComparable(a, b);
    Image8 out = a;
    for (std::size_t p = 0; p < std::size_t(a.width) * std::size_t(a.height); ++p) {
        std::uint8_t* o = &out.rgba[p * 4];
        const int difference = pixelDifference(a, b, p);
        if (difference > tolerance) {
            // 1 level over the tolerance is already clearly red; 8 over is full red.
            o[0] = std::uint8_t(std::min(255, 144 + 16 * (difference - tolerance)));
            o[1] = o[2] = 0;
        } else {
            // Dim grey (at most 1/3 brightness) keeps the picture readable behind the red.
            const int grey = (o[0] + o[1] + o[2]) / 9;
            o[0] = o[1] = o[2] = std::uint8_t(grey);
        }
        o[3] = 255;
    }
    return out;
}

std::string describe(const ImageComparison& comparison) {
    // Rounded down, so "100%" is printed only when every pixel matches.
    const double percent = std::floor(comparison.fractionWithinTolerance * 10000.0) / 100.0;
    char text[256];
    if (comparison.pixelsWithinTolerance == comparison.pixels)
        std::snprintf(text, sizeof text, "100%% of %ld pixels", comparison.pixels);
    else
        std::snprintf(text, sizeof text, "%.2f%% of %ld pixels", percent, comparison.pixels);
    std::string result = text;
    std::snprintf(text, sizeof text, " within %d/255, max diff %d/255 at (%d,%d), RMSE %.2f",
                  comparison.tolerance, comparison.maxChannelDifference, comparison.worstX,
                  comparison.worstY, comparison.rmse);
    return result + text;
}
