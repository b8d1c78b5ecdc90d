#include "reference_range.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>

namespace {

// the default camera through the point (px, py) of the image, in pixels from the top left.
glm::dvec3 eyeDirection(const ReferenceSettings& settings, double px, double py) {
    const double tanHalfY = std::tan(settings.fovDegrees * (std::numbers::pi / 360.0));
    const double tanHalfX = double(settings.width) / settings.height * tanHalfY;
    return glm::normalize(glm::dvec3((2.0 * px / settings.width - 1.0) * tanHalfX,
                                     (1.0 - 2.0 * py / settings.height) * tanHalfY, -1.0));
}

std::size_t pixelIndex(const Image8& image, int x, int y) {
    return std::size_t(y) * std::size_t(image.width) + std::size_t(x);
}

} // namespace

ReferenceRange::ReferenceRange(const Scene& scene, const ReferenceSettings& settings,
                               PerturbationSettings perturbation)
    : scene_(scene), settings_(settings) {
    if (settings.spp != 1)
        throw std::invalid_argument("the reference range is defined for one sample per pixel");
    centre_ = renderReference(scene, settings);
    const double pixelRadians =
        2.0 * std::tan(settings.fovDegrees * (std::numbers::pi / 360.0)) / settings.height;
    delta_ = std::max(perturbation.minimumPixels, perturbation.minimumRadians / pixelRadians);
    const std::size_t pixels = std::size_t(settings.width) * std::size_t(settings.height);
    low_.resize(pixels * 3);
    high_.resize(pixels * 3);
    known_.assign(pixels, false);
}

void ReferenceRange::ensure(int x, int y) {
    const std::size_t p = pixelIndex(centre_, x, y);
    if (known_[p]) return;
    known_[p] = true;
    for (int c = 0; c < 3; ++c)
        low_[p * 3 + std::size_t(c)] = high_[p * 3 + std::size_t(c)] =
            centre_.rgba[p * 4 + std::size_t(c)];
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const glm::dvec3 color =
                traceEyeRay(scene_, settings_,
                            eyeDirection(settings_, x + 0.5 + dx * delta_, y + 0.5 + dy * delta_));
            for (int c = 0; c < 3; ++c) {
                const auto byte = std::uint8_t(quantizeChannel(color[c], settings_.truncate));
                std::uint8_t& lo = low_[p * 3 + std::size_t(c)];
                std::uint8_t& hi = high_[p * 3 + std::size_t(c)];
                lo = std::min(lo, byte);
                hi = std::max(hi, byte);
            }
        }
}

std::uint8_t ReferenceRange::low(int x, int y, int c) {
    ensure(x, y);
    return low_[pixelIndex(centre_, x, y) * 3 + std::size_t(c)];
}

std::uint8_t ReferenceRange::high(int x, int y, int c) {
    ensure(x, y);
    return high_[pixelIndex(centre_, x, y) * 3 + std::size_t(c)];
}

namespace {

enum class Verdict { Matches, Excused, Wrong };

// How far (in levels) the pixel lies outside its reference range, and the verdict.
Verdict judge(const Image8& image, ReferenceRange& range, int x, int y, int tolerance,
              int& excess) {
    const std::size_t p = pixelIndex(image, x, y);
    const Image8& centre = range.centre();
    int difference = 0;
    for (std::size_t c = 0; c < 3; ++c)
        difference = std::max(difference,
                              std::abs(int(image.rgba[p * 4 + c]) - int(centre.rgba[p * 4 + c])));
    excess = 0;
    if (difference <= tolerance) return Verdict::Matches;
    for (int c = 0; c < 3; ++c) {
        const int value = image.rgba[p * 4 + std::size_t(c)];
        excess =
            std::max({excess, int(range.low(x, y, c)) - value, value - int(range.high(x, y, c))});
    }
    return excess > tolerance ? Verdict::Wrong : Verdict::Excused;
}

void checkSize(const Image8& image, ReferenceRange& range) {
    const Image8& centre = range.centre();
    if (image.width != centre.width || image.height != centre.height ||
        image.rgba.size() != centre.rgba.size())
        throw std::invalid_argument("image is " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ", the reference " +
                                    std::to_string(centre.width) + "x" +
                                    std::to_string(centre.height));
}

} // namespace

StabilityCount countWrongPixels(const Image8& image, ReferenceRange& range, int tolerance) {
    checkSize(image, range);
    StabilityCount count;
    count.pixels = long(image.width) * long(image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            int excess = 0;
            const Verdict verdict = judge(image, range, x, y, tolerance, excess);
            count.differing += verdict != Verdict::Matches;
            count.wrong += verdict == Verdict::Wrong;
            if (verdict == Verdict::Wrong && excess > count.worstExcess) {
                count.worstExcess = excess;
                count.worstX = x;
                count.worstY = y;
            }
        }
    count.failureRate = double(count.wrong) / double(count.pixels);
    return count;
}

Image8 wrongPixelImage(const Image8& image, ReferenceRange& range, int tolerance) {
    checkSize(image, range);
    Image8 out = image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            int excess = 0;
            const Verdict verdict = judge(image, range, x, y, tolerance, excess);
            std::uint8_t* p = &out.rgba[pixelIndex(image, x, y) * 4];
            const std::uint8_t grey = std::uint8_t((p[0] + p[1] + p[2]) / 12 + 32);
            if (verdict == Verdict::Wrong) {
                p[0] = 255, p[1] = 0, p[2] = 0;
            } else if (verdict == Verdict::Excused) {
                p[0] = 255, p[1] = 220, p[2] = 0;
            } else {
                p[0] = p[1] = p[2] = grey;
            }
            p[3] = 255;
        }
    return out;
}
