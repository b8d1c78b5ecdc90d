#include "packing/bvh_node.h"

#include <bit>
#include <stdexcept>
#include <string>

namespace {

// The two sides of a node's fields (shared.h).
struct ChildFields {
    const glm::vec4& minAndRef;
    const glm::vec4& max;
};

ChildFields fields(const gpu::GpuBvhNode& node, BvhSide side) {
    if (side == BvhSide::Left) return {node.leftMinAndRef, node.leftMax};
    return {node.rightMinAndRef, node.rightMax};
}

} // namespace

BvhChild bvhChild(const gpu::GpuBvhNode& node, BvhSide side) {
    const ChildFields f = fields(node, side);
    const std::uint32_t reference = std::bit_cast<std::uint32_t>(f.minAndRef.w);
    BvhChild child{glm::vec3(f.minAndRef), glm::vec3(f.max)};
    child.leaf = (reference & BVH_LEAF) != 0;
    if (!child.leaf) {
        child.index = reference;
        return child;
    }
    child.index = reference & BVH_FIRST_MASK;
    child.count = (reference >> BVH_COUNT_SHIFT) & BVH_MAX_LEAF_COUNT;
    child.spheres = (reference & BVH_LEAF_SPHERES) != 0;
    return child;
}

void setBvhChild(gpu::GpuBvhNode& node, BvhSide side, const BvhChild& child) {
    if (child.leaf && child.count > BVH_MAX_LEAF_COUNT)
        throw std::invalid_argument("setBvhChild: a leaf of " + std::to_string(child.count) +
                                    " primitives does not fit its count field");
    if (child.leaf && child.index > BVH_FIRST_MASK)
        throw std::invalid_argument("setBvhChild: a leaf's first primitive " +
                                    std::to_string(child.index) + " does not fit its reference");
    if (!child.leaf && child.index >= BVH_LEAF)
        throw std::invalid_argument("setBvhChild: node index " + std::to_string(child.index) +
                                    " does not fit its reference");
    const std::uint32_t reference = child.leaf
                                        ? BVH_LEAF | (child.spheres ? BVH_LEAF_SPHERES : 0u) |
                                              child.count << BVH_COUNT_SHIFT | child.index
                                        : child.index;
    const glm::vec4 minAndRef(child.lo, std::bit_cast<float>(reference));
    const glm::vec4 max(child.hi, 0.0f);
    if (side == BvhSide::Left) {
        node.leftMinAndRef = minAndRef;
        node.leftMax = max;
    } else {
        node.rightMinAndRef = minAndRef;
        node.rightMax = max;
    }
}
