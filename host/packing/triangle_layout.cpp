#include "packing/triangle_layout.h"

#include <glm/glm.hpp>

TriangleLayoutBytes triangleLayoutBytes(const PackedScene& packed) {
    const bool fp64 = !packed.vertexPositions64.empty();
    const std::uint64_t position = fp64 ? sizeof(glm::dvec4) : sizeof(glm::vec4);
    const std::uint64_t triangles = packed.triangles.size();
    const std::uint64_t vertices = packed.vertexPositions.size();
    return {triangles * (3 * position + sizeof(std::uint32_t)),
            triangles * sizeof(glm::uvec4) + vertices * position};
}

bool indexedTriangles(const PackedScene& packed, TriangleLayout layout, const LayoutRoom& room) {
    if (layout != TriangleLayout::Auto) return layout == TriangleLayout::Indexed;
    if (!room.cornersFit) return true;
    const TriangleLayoutBytes bytes = triangleLayoutBytes(packed);
    return room.deviceMemory > 0 && bytes.corners > room.deviceMemory / kCornersShareOfMemory &&
           bytes.indexed < bytes.corners;
}

void allowTriangleLayouts(SceneCapacity& capacity, TriangleLayout layout) {
    capacity.cornersAllowed = layout != TriangleLayout::Indexed;
    capacity.indexedAllowed = layout != TriangleLayout::Corners;
}
