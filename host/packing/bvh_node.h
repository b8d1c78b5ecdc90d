// A hierarchy node's two child references (shared.h's GpuBvhNode), decoded and encoded:
// an interior child's node index, or a leaf's first slot, count and kind, with its box.
#pragma once

#include "shared.h"

#include <glm/glm.hpp>

#include <cstdint>

// A node's child reference (shared.h), decoded: what the shader reads from one side.
struct BvhChild {
    glm::vec3 lo{0.0f}, hi{0.0f}; // its box
    bool leaf = false;
    std::uint32_t index = 0; // interior: its node index; leaf: its first primitive slot
    std::uint32_t count = 0; // leaf: its primitive count (0: the empty leaf of a lone root leaf)
    bool spheres = false;    // leaf: its primitives are spheres, else triangles
    bool operator==(const BvhChild&) const = default;
};

enum class BvhSide { Left, Right };

BvhChild bvhChild(const gpu::GpuBvhNode& node, BvhSide side);
// Stores child on that side of node; throws when a leaf's count does not fit its word.
void setBvhChild(gpu::GpuBvhNode& node, BvhSide side, const BvhChild& child);
