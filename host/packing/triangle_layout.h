// How the GPU holds a scene's triangles (shaders/shared.h, SPEC_INDEXED_TRIANGLES), chosen
// per scene by --triangle-layout.
// - Corners: three positions a triangle, each with a word (flat patch, vertex indices), and
//   the last vertex index apart: 52 bytes a triangle (100 in fp64). A ray test's three
//   fetches are independent of each other.
// - Indexed: the triangle's vertex indices and flat patch (16 bytes) and each vertex's
//   position once (16 bytes, 32 in fp64). A ray test first fetches the indices, then the
//   positions: a dependent fetch more, for fewer bytes where triangles share vertices.
// Both hold the very same floats (or doubles), so the images are the same.
#pragma once

#include "packing/scene_packing.h"
#include "scene/scene_capacity.h"

#include <cstddef>
#include <cstdint>

enum class TriangleLayout { Auto, Corners, Indexed };

// The triangles' bytes on the GPU in each layout (the vertices' normals and materials,
// the same in both, left out).
struct TriangleLayoutBytes {
    std::uint64_t corners = 0;
    std::uint64_t indexed = 0;
};
TriangleLayoutBytes triangleLayoutBytes(const PackedScene& packed);

// Auto takes indexed triangles for a scene of this many triangles or more when they take
// fewer bytes than corners (a mesh whose triangles share their vertices; not one whose
// triangles each have their own three, as in the classic scenes with a material a vertex).
// Smaller scenes keep corners, the faster to trace, whose bytes are then no concern.
constexpr std::size_t kIndexedAutoTriangles = 1000000;

// Whether the scene's triangles go indexed: as asked, or for Auto as above, or when the
// corners would not fit the device (cornersFit false).
bool indexedTriangles(const PackedScene& packed, TriangleLayout layout, bool cornersFit);

// Lets the early check (scene_capacity.h) count the layouts `layout` may take: one, or
// for Auto both.
void allowTriangleLayouts(SceneCapacity& capacity, TriangleLayout layout);
