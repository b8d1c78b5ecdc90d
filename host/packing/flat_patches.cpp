#include "packing/flat_patches.h"

#include "base/keyed_lists.h"
#include "base/parallel.h"
#include "base/populated_memory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace {

struct Plane {
    glm::dvec3 normal{0.0}; // unit; zero for a triangle of zero area
    double offset = 0.0;    // dot(normal, any point of the plane)
    double tolerance = 0.0; // kFlatTolerance times the triangle's largest coordinate
};

Plane planeOf(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    Plane plane;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length)) return plane;
    plane.normal = n / length;
    plane.offset = glm::dot(plane.normal, a);
    const glm::dvec3 largest = glm::max(glm::abs(a), glm::max(glm::abs(b), glm::abs(c)));
    plane.tolerance = kFlatTolerance * std::max({largest.x, largest.y, largest.z});
    return plane;
}

// A triangle of nonzero area as the flat test reads it, its plane and corners read once for
// all the tests at a vertex rather than through the corner indices at each.
struct FlatTest {
    std::uint32_t triangle = 0;
    Plane plane;
    glm::dvec3 corners[3];
};

// Whether every corner of t lies in u's plane, to within the larger of their tolerances.
bool liesIn(const FlatTest& t, const FlatTest& u) {
    for (const glm::dvec3& corner : t.corners) {
        const double distance = glm::dot(u.plane.normal, corner) - u.plane.offset;
        if (!(std::abs(distance) <= std::max(u.plane.tolerance, t.plane.tolerance))) return false;
    }
    return true;
}

// Both ways, so that a sliver's ill-determined normal cannot join a triangle it is not flat
// with.
bool flat(const FlatTest& t, const FlatTest& u) {
    return liesIn(t, u) && liesIn(u, t);
}

// Disjoint sets with path halving.
struct Patches {
    std::vector<std::uint32_t> parent;
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

// cornerAt(t, k): the index into positions of triangle t's corner k.
template <typename CornerAt>
std::vector<std::uint32_t> patchesOf(const std::vector<glm::dvec3>& positions,
                                     std::size_t triangleCount, const CornerAt& cornerAt) {
    std::vector<Plane> planes;
    resizePopulated(planes, triangleCount);
    const std::vector<IndexRange> triangleRanges = splitRange(triangleCount, 16384);
    parallelFor(triangleRanges.size(), [&](std::size_t r) {
        for (std::size_t t = triangleRanges[r].begin; t < triangleRanges[r].end; ++t)
            planes[t] = planeOf(positions[cornerAt(t, 0)], positions[cornerAt(t, 1)],
                                positions[cornerAt(t, 2)]);
    });

    // The triangles at each vertex.
    const KeyedLists trianglesAt = keyedLists(positions.size(), triangleCount, 3 * triangleCount,
                                              [&](std::size_t t, const auto& visit) {
                                                  for (int k = 0; k < 3; ++k)
                                                      visit(cornerAt(t, k));
                                              });

    // The joins at a vertex follow from the planes alone, not from the joins before them,
    // so the vertices are visited on all threads, a batch of ranges at a time, and their
    // joins made after each batch: a patch's number is its smallest triangle's (join keeps
    // the smaller root), whatever order its triangles were joined in.
    Patches patches;
    resizePopulated(patches.parent, triangleCount);
    parallelForRanges(triangleCount, 1 << 16, [&](IndexRange range) {
        std::iota(patches.parent.begin() + std::ptrdiff_t(range.begin),
                  patches.parent.begin() + std::ptrdiff_t(range.end), std::uint32_t(range.begin));
    });
    const std::vector<IndexRange> vertexRanges = splitRange(positions.size(), 16384);
    constexpr std::size_t kRangesABatch = 64;
    std::vector<std::vector<std::array<std::uint32_t, 2>>> joins(kRangesABatch);
    for (std::size_t first = 0; first < vertexRanges.size(); first += kRangesABatch) {
        const std::size_t count = std::min(kRangesABatch, vertexRanges.size() - first);
        parallelFor(count, [&](std::size_t i) {
            joins[i].clear();
            for (std::size_t v = vertexRanges[first + i].begin; v < vertexRanges[first + i].end;
                 ++v) {
                FlatTest representatives[kPlanesPerVertex];
                int planeCount = 0;
                for (std::uint32_t at = trianglesAt.start[v]; at < trianglesAt.start[v + 1]; ++at) {
                    const std::uint32_t t = trianglesAt.items[at];
                    if (planes[t].tolerance == 0.0) continue;
                    const FlatTest triangle{t,
                                            planes[t],
                                            {positions[cornerAt(t, 0)], positions[cornerAt(t, 1)],
                                             positions[cornerAt(t, 2)]}};
                    int k = 0;
                    while (k < planeCount && !flat(triangle, representatives[k]))
                        ++k;
                    if (k < planeCount)
                        joins[i].push_back({t, representatives[k].triangle});
                    else if (planeCount < kPlanesPerVertex)
                        representatives[planeCount++] = triangle;
                }
            }
        });
        for (std::size_t i = 0; i < count; ++i)
            for (const auto& [t, u] : joins[i])
                patches.join(t, u);
    }
    // Every join made: the roots are read on all threads, without find's path halving.
    std::vector<std::uint32_t> patchOf;
    resizePopulated(patchOf, triangleCount);
    parallelForRanges(triangleCount, 1 << 16, [&](IndexRange range) {
        for (std::size_t t = range.begin; t < range.end; ++t) {
            std::uint32_t root = std::uint32_t(t);
            while (patches.parent[root] != root)
                root = patches.parent[root];
            patchOf[t] = root;
        }
    });
    return patchOf;
}

} // namespace

std::vector<std::uint32_t> flatPatches(const std::vector<glm::dvec3>& positions,
                                       const std::vector<std::uint32_t>& triangleVertices) {
    return patchesOf(positions, triangleVertices.size() / 3, [&](std::size_t t, int k) {
        return triangleVertices[3 * t + std::size_t(k)];
    });
}

std::vector<std::uint32_t> flatPatches(const std::vector<glm::dvec3>& positions,
                                       const std::vector<glm::uvec4>& triangles,
                                       const std::vector<std::uint32_t>& positionOf) {
    return patchesOf(positions, triangles.size(),
                     [&](std::size_t t, int k) { return positionOf[triangles[t][k]]; });
}
