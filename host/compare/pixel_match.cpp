#include "compare/pixel_match.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace {

bool within(const float* a, const float* b, double tolerance) {
    return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance &&
           std::abs(a[2] - b[2]) <= tolerance;
}

// Labels the 8-connected sets of non-matching pixels and measures each: the regions worst
// first, and each pixel's index among them (-1 where it matches) in regionOf.
std::vector<MismatchRegion> findRegions(const PixelMatch& match, std::vector<int>& regionOf) {
    const int w = match.width, h = match.height;
    std::vector<int> label(std::size_t(w) * std::size_t(h), -1);
    std::vector<MismatchRegion> regions;
    std::vector<std::size_t> stack;
    for (std::size_t start = 0; start < label.size(); ++start) {
        if (match.matches[start] || label[start] >= 0) continue;
        MismatchRegion region;
        region.left = region.right = int(start % std::size_t(w));
        region.top = region.bottom = int(start / std::size_t(w));
        const int id = int(regions.size());
        label[start] = id;
        stack.push_back(start);
        while (!stack.empty()) {
            const std::size_t at = stack.back();
            stack.pop_back();
            const int x = int(at % std::size_t(w)), y = int(at / std::size_t(w));
            region.left = std::min(region.left, x);
            region.right = std::max(region.right, x);
            region.top = std::min(region.top, y);
            region.bottom = std::max(region.bottom, y);
            ++region.pixels;
            region.meanSignedDifference += match.signedDifference[at];
            region.sumAbsoluteDifference += std::abs(match.signedDifference[at]);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::size_t next = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                    if (match.matches[next] || label[next] >= 0) continue;
                    label[next] = id;
                    stack.push_back(next);
                }
        }
        region.meanSignedDifference /= double(region.pixels);
        regions.push_back(region);
    }
    std::vector<int> order(regions.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        order[k] = int(k);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return regions[std::size_t(a)].sumAbsoluteDifference >
               regions[std::size_t(b)].sumAbsoluteDifference;
    });
    std::vector<int> rank(regions.size());
    std::vector<MismatchRegion> sorted;
    for (std::size_t k = 0; k < order.size(); ++k) {
        rank[std::size_t(order[k])] = int(k);
        sorted.push_back(regions[std::size_t(order[k])]);
    }
    regionOf.assign(label.size(), -1);
    for (std::size_t p = 0; p < label.size(); ++p)
        if (label[p] >= 0) regionOf[p] = rank[std::size_t(label[p])];
    return sorted;
}

} // namespace

PixelMatch matchPixels(const ImageF& image, const ImageF& expected, double tolerance) {
    if (image.width != expected.width || image.height != expected.height)
        throw std::invalid_argument("images of different sizes: " + std::to_string(image.width) +
                                    "x" + std::to_string(image.height) + " and " +
                                    std::to_string(expected.width) + "x" +
                                    std::to_string(expected.height));
    PixelMatch match;
    match.width = image.width;
    match.height = image.height;
    match.tolerance = tolerance;
    match.pixels = long(image.width) * long(image.height);
    match.signedDifference.resize(std::size_t(match.pixels));
    match.matches.resize(std::size_t(match.pixels));
    double absoluteSum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::size_t at = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            const float* mine = &image.rgb[at * 3];
            const float* wanted = &expected.rgb[at * 3];
            bool matches = within(mine, wanted, tolerance);
            for (int dy = -1; dy <= 1 && !matches; ++dy)
                for (int dx = -1; dx <= 1 && !matches; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) continue;
                    matches = within(
                        mine, &expected.rgb[(std::size_t(ny) * std::size_t(image.width) + nx) * 3],
                        tolerance);
                }
            match.matches[at] = matches;
            match.matching += matches;
            match.signedDifference[at] =
                float((mine[0] - wanted[0] + mine[1] - wanted[1] + mine[2] - wanted[2]) / 3.0);
            absoluteSum += std::abs(mine[0] - wanted[0]) + std::abs(mine[1] - wanted[1]) +
                           std::abs(mine[2] - wanted[2]);
        }
    match.fractionMatching = double(match.matching) / double(std::max(match.pixels, 1L));
    match.meanAbsoluteDifference = absoluteSum / double(3 * std::max(match.pixels, 1L));
    match.regions = findRegions(match, match.regionOf);
    return match;
}
