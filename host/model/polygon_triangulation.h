// A model's polygon split into triangles: a fan from its first corner when the polygon is
// convex (as OBJ readers always have), ear clipping when it is concave and planar (a ring,
// a letter: a fan would fill what the polygon leaves open), and a fan again, counted as
// it, when it is concave and bent out of its plane or crossing itself (no split is right).
// tools/obj_to_scene.py does the same, operation for operation.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <vector>

struct PolygonTriangles {
    std::vector<std::array<std::size_t, 3>> triangles; // indices into the polygon's corners
    bool fannedConcave = false; // concave, and not planar or crossing itself: fanned
};

// A corner further from the polygon's plane than this share of its reach from the first
// corner makes a concave polygon non-planar.
inline constexpr double kPlanarTolerance = 1e-4;

PolygonTriangles triangulatePolygon(const std::vector<glm::dvec3>& corners);
