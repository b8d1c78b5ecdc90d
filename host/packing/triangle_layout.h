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

// What Auto weighs of the device.
struct LayoutRoom {
    bool cornersFit = true;         // the corners are within its limits (scene_capacity.h)
    std::uint64_t deviceMemory = 0; // its largest device-local heap in bytes; 0: not known
};

// Auto keeps corners, the faster to trace (indexed costs lavapipe 5-8% of a frame at a
// million triangles), unless they do not fit the device, or take more than this share of
// its memory where indexed takes fewer bytes (a mesh whose triangles share their vertices;
// not one whose triangles each have their own three, as the classic scenes').
constexpr std::uint64_t kCornersShareOfMemory = 8; // 1/8

// Whether the scene's triangles go indexed: as asked, or for Auto as above.
bool indexedTriangles(const PackedScene& packed, TriangleLayout layout, const LayoutRoom& room);

// Lets the early check (scene_capacity.h) count the layouts `layout` may take: one, or
// for Auto both.
void allowTriangleLayouts(SceneCapacity& capacity, TriangleLayout layout);
