#include "model/smooth_normals.h"

#include "base/parallel.h"
#include "base/populated_memory.h"
#include "model/exact_vectors.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace {

using namespace exact_vectors;

constexpr double kPi = 3.141592653589793;
constexpr std::size_t kNoFace = SIZE_MAX;

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
    double largest = 0.0;
    for (const glm::dvec3& p : positions)
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    int exponent = 0;
    std::frexp(largest, &exponent);
    return std::ldexp(1.0, -exponent);
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
    // The faces around each position in one array, each face once though its position
    // repeats: counted, then placed.
    resizePopulated(start_, positions.size() + 1);
    auto eachCorner = [&](auto visit) {
        for (std::size_t f = 0; f < faces; ++f)
            if (leftOut.empty() || !leftOut[f])
                for (const std::uint32_t p : facePositions(model, f))
                    visit(static_cast<std::uint32_t>(f), p);
    };
    std::vector<std::size_t> next(positions.size(), kNoFace); // the last face counted
    eachCorner([&](std::uint32_t f, std::uint32_t p) {
        if (next[p] != f) next[p] = f, ++start_[p + 1];
    });
    for (std::size_t p = 0; p < positions.size(); ++p)
        start_[p + 1] += start_[p];
    resizePopulated(faces_, start_.back());
    std::copy(start_.begin(), start_.end() - 1, next.begin()); // where p's next face goes
    eachCorner([&](std::uint32_t f, std::uint32_t p) {
        if (next[p] == start_[p] || faces_[next[p] - 1] != f) faces_[next[p]++] = f;
    });
}

glm::dvec3 SmoothNormals::at(std::uint32_t face, std::uint32_t position) const {
    glm::dvec3 sum(0.0);
    for (std::size_t i = start_[position]; i < start_[position + 1]; ++i) {
        const std::uint32_t other = faces_[i];
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
