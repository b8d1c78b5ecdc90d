// Flat patches: the connected sets of coplanar triangles of a mesh (a quad's two halves, a
// box's face, a tessellated ground). A ray that leaves a flat surface cannot meet it again,
// so with --offset error-bound the kernel skips every triangle of the patch a ray leaves
// (shaders/ray_offset.glsl): the offset follows the hit point's own rounding error, which
// is smaller than the error of the triangle test for a neighbour whose vertices lie far
// from the point, and that neighbour could otherwise be met at a tiny t.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

// Per triangle (three indices each into positions), the number of its flat patch: triangles
// that share a vertex and lie in one plane, to within kFlatTolerance of their largest
// coordinate, share a number, and so do chains of such triangles. A triangle of zero area
// has a patch of its own. At most kPlanesPerVertex planes are told apart at one vertex (a
// cone's apex meets as many planes as it has sides): a triangle in a further plane there is
// joined through its other vertices or not at all, which only leaves patches smaller.
std::vector<std::uint32_t> flatPatches(const std::vector<glm::dvec3>& positions,
                                       const std::vector<std::uint32_t>& triangleVertices);

// The same, triangle t's corners being positions[positionOf[triangles[t][k]]] (k < 3): the
// packer's triangles, whose vertices share positions, without an array of their corners.
std::vector<std::uint32_t> flatPatches(const std::vector<glm::dvec3>& positions,
                                       const std::vector<glm::uvec4>& triangles,
                                       const std::vector<std::uint32_t>& positionOf);

// 2^-20 of a coordinate: 16 float ULPs, so vertices written as coplanar in the scene file
// stay coplanar after their rounding to float.
constexpr double kFlatTolerance = 1.0 / 1048576.0;
constexpr int kPlanesPerVertex = 8;
