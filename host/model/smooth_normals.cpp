#include "model/smooth_normals.h"

#include "base/keyed_lists.h"
#include "base/parallel.h"
#include "base/populated_memory.h"
#include "model/exact_vectors.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace {

using namespace exact_vectors;

constexpr double kPi = 3.141592653589793;

// The crease test compares the faces' unit normals in double, as the rule says, but first
// their float roundings: each component within 2^-24 of its own, so the two dot products
// differ by under 2e-7. Only a pair this close to the crease angle is compared again in
// double; every other pair is decided alike by both.
constexpr double kCreaseMargin = 1e-6;

double roundedDot(const glm::vec3& a, const glm::vec3& b) {
    return double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z;
}

// Newell's sum of cross products over a polygon: its normal scaled by twice its area, so
// adding such sums weights faces by area; per polygon, so how a quad was split does not
// tilt its corners' normals.
// The positions are multiplied by scale, a power of two, which changes no rounding.
glm::dvec3 newellNormal(const std::vector<glm::dvec3>& positions,
                        std::span<const std::uint32_t> face, double scale) {
    glm::dvec3 normal(0.0);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
        const glm::dvec3 a = positions[face[0]] * scale;
        normal += glm::cross(positions[face[i]] * scale - a, positions[face[i + 1]] * scale - a);
    }
    return normal;
}

// The power of two that brings the largest coordinate into [0.5, 1): the Newell normals of
// a model at 1e300 would overflow to infinity (and its normals be NaN), while for every
// other model the scaled arithmetic rounds exactly as the unscaled one, so its normals are
// the same bits.
double newellScale(const std::vector<glm::dvec3>& positions) {
    const double largest = reduceRanges(
        positions.size(), 1 << 15,
        [&](IndexRange range) {
            double part = 0.0;
            for (std::size_t i = range.begin; i < range.end; ++i) {
                const glm::dvec3& p = positions[i];
                part = std::max({part, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
            }
            return part;
        },
        [](double part, double& into) { into = std::max(into, part); });
    int exponent = 0;
    std::frexp(largest, &exponent);
    return std::ldexp(1.0, -exponent);
}

// visit(p) for each position of the face once, however often the face names it: by a look
// back over a small face, by sorting a copy of a large one.
template <typename Visit>
void visitEachOnce(std::span<const std::uint32_t> face, const Visit& visit) {
    constexpr std::size_t kLookBack = 16;
    if (face.size() <= kLookBack) {
        for (std::size_t i = 0; i < face.size(); ++i)
            if (std::find(face.begin(), face.begin() + i, face[i]) == face.begin() + i)
                visit(face[i]);
        return;
    }
    std::vector<std::uint32_t> sorted(face.begin(), face.end());
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i)
        if (i == 0 || sorted[i] != sorted[i - 1]) visit(sorted[i]);
}

} // namespace

SmoothNormals::SmoothNormals(const SourceModel& model, const std::vector<glm::dvec3>& positions,
                             double creaseDegrees, const std::vector<bool>& leftOut)
    : cosine_(std::cos(creaseDegrees * (kPi / 180.0))), everywhere_(creaseDegrees >= 180.0) {
    const std::size_t faces = faceCount(model);
    const double scale = newellScale(positions);
    // Their pages mapped on all threads: a fresh page's first touch costs more than what is
    // written into it (base/populated_memory.h).
    resizePopulated(newell_, faces);
    resizePopulated(unit_, faces);
    const std::vector<IndexRange> ranges = splitRange(faces, 4096);
    parallelFor(ranges.size(), [&](std::size_t k) {
        for (std::size_t f = ranges[k].begin; f < ranges[k].end; ++f) {
            newell_[f] = newellNormal(positions, facePositions(model, f), scale);
            unit_[f] = glm::vec3(normalizedOrZero(newell_[f]));
        }
    });
    // The faces around each position, each face once though its position repeats in it.
    facesAt_ = keyedLists(positions.size(), faces, facePositionCount(model),
                          [&](std::size_t f, const auto& visit) {
                              if (leftOut.empty() || !leftOut[f])
                                  visitEachOnce(facePositions(model, f), visit);
                          });
    // A position whose faces are each within the crease angle of every other (all of a
    // smooth surface's) gives every face there the sum of all of them: made once here
    // rather than at each of its corners, with half the crease tests that at's calls make.
    resizePopulated(shared_, positions.size());
    resizePopulated(sharedNormal_, positions.size());
    parallelForRanges(positions.size(), 4096, [&](IndexRange range) {
        for (std::size_t p = range.begin; p < range.end; ++p) {
            shared_[p] = allWithinCrease(std::uint32_t(p));
            if (shared_[p]) sharedNormal_[p] = sumAround(std::uint32_t(p));
        }
    });
}

bool SmoothNormals::allWithinCrease(std::uint32_t position) const {
    if (everywhere_) return true;
    const std::uint32_t first = facesAt_.start[position], end = facesAt_.start[position + 1];
    for (std::uint32_t i = first; i < end; ++i)
        for (std::uint32_t j = i + 1; j < end; ++j)
            if (!withinCrease(facesAt_.items[i], facesAt_.items[j])) return false;
    return true;
}

glm::dvec3 SmoothNormals::sumAround(std::uint32_t position) const {
    glm::dvec3 sum(0.0);
    for (std::uint32_t i = facesAt_.start[position]; i < facesAt_.start[position + 1]; ++i)
        sum += newell_[facesAt_.items[i]];
    return normalizedOrZero(sum);
}

glm::dvec3 SmoothNormals::at(std::uint32_t face, std::uint32_t position) const {
    if (shared_[position]) return sharedNormal_[position];
    glm::dvec3 sum(0.0);
    for (std::uint32_t i = facesAt_.start[position]; i < facesAt_.start[position + 1]; ++i) {
        const std::uint32_t other = facesAt_.items[i];
        if (everywhere_ || other == face || withinCrease(face, other)) sum += newell_[other];
    }
    return normalizedOrZero(sum);
}

bool SmoothNormals::withinCrease(std::uint32_t face, std::uint32_t other) const {
    const double rounded = roundedDot(unit_[face], unit_[other]);
    if (rounded - cosine_ > kCreaseMargin) return true;
    if (cosine_ - rounded > kCreaseMargin) return false;
    return dot(normalizedOrZero(newell_[face]), normalizedOrZero(newell_[other])) >=
           cosine_; // NaN comes here too
}
