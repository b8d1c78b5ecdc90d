// An image against the image it should be, pixel by pixel, as course graders compare: a
// pixel matches when every channel is within the tolerance of the expected pixel or of one
// of its eight neighbours (so that an edge anti-aliased or placed half a pixel off is not
// an error). What does not match is grouped into regions of touching pixels.
#pragma once

#include "base/float_image.h"

#include <vector>

// Touching pixels (8-connected) that do not match.
struct MismatchRegion {
    int left = 0, top = 0, right = 0, bottom = 0; // inclusive bounds
    long pixels = 0;
    double meanSignedDifference = 0;  // image minus expected, mean over pixels and channels
    double sumAbsoluteDifference = 0; // over pixels, of the channel mean: how bad it is
};

struct PixelMatch {
    int width = 0, height = 0;
    double tolerance = 0;
    long pixels = 0, matching = 0;
    double fractionMatching = 0;
    double meanAbsoluteDifference = 0; // over all pixels and channels, levels
    // Per pixel: image minus expected, mean over channels (the heat map), and whether it
    // matches.
    std::vector<float> signedDifference;
    std::vector<unsigned char> matches;
    std::vector<MismatchRegion> regions; // worst first: the largest sum of differences
    std::vector<int> regionOf;           // per pixel: its index in regions, -1 if it matches
};

// image and expected: RGB levels 0..255 of the same size (std::invalid_argument if not).
PixelMatch matchPixels(const ImageF& image, const ImageF& expected, double tolerance);
