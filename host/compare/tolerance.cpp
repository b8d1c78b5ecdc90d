#include "compare/tolerance.h"

#include <algorithm>
#include <array>
#include <utility>

namespace {

constexpr double kExactTolerance = 2;

// (quality, tolerance): the smallest tolerance at which 99.5% of the pixels of correct
// renders of the classic scenes and the project's own, saved as JPEG by stb (not libjpeg),
// match the reference written as that JPEG was; the worst scene per quality, measured with
// tools/compare/jpeg_tolerance.py (docs/compare.md; below 50 on five of the scenes). A
// quality between two rows takes the lower row's tolerance, one below 10 the first row's.
constexpr std::array<std::pair<int, double>, 9> kJpegTolerance = {
    {{10, 17}, {25, 11}, {40, 7}, {50, 6}, {75, 5}, {85, 5}, {90, 4}, {95, 4}, {100, 2}}};

} // namespace

Tolerance toleranceFor(const HandedInImage& image) {
    if (image.format != HandedInFormat::Jpeg)
        return {kExactTolerance, std::string("exact ") + formatName(image.format)};
    if (!image.jpegQuality)
        return {kJpegTolerance.front().second,
                "JPEG of unknown quality (no standard tables): held as quality 10"};
    const int quality = *image.jpegQuality;
    double levels = kJpegTolerance.front().second;
    for (const auto& [atLeast, tolerance] : kJpegTolerance)
        if (quality >= atLeast) levels = tolerance;
    return {levels, "JPEG quality " + std::to_string(quality) + ", estimated from its tables"};
}
