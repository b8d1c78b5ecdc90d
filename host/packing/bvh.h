// Bounding volume hierarchy over spheres and triangles together, built on the host with
// a binned surface-area heuristic and flattened into the GpuBvhNode array of shared.h
// (two-wide nodes holding both children's boxes; leaves live in their parent's reference).
// Knows nothing of Vulkan or of the scene file: it sees one box per primitive.
#pragma once

#include "packing/bvh_node.h"
#include "shared.h"

#include <cstddef>
#include <cstdint>
#include <vector>

// A primitive's axis-aligned box, laid out as the builder partitions it in place (half a
// cache line; packing/bvh_boxes.h), so that it builds in the caller's array, not in a copy.
struct PrimitiveBox {
    float lo[3];          // min x y z
    std::uint32_t id = 0; // the builder's: it numbers the primitives here
    float hi[3];          // max x y z
    float zero = 0.0f;    // the builder's: 0
};

// One box per primitive: the input of the builder.
struct PrimitiveBounds {
    std::vector<PrimitiveBox> boxes;
    std::uint32_t sphereCount = 0; // primitives [0, sphereCount) are spheres, the rest triangles
    std::size_t size() const { return boxes.size(); }
};

// Whether the shader walks a hierarchy or tests every primitive (--accel).
enum class Acceleration { Auto, Bvh, None };

// Auto uses the hierarchy from this many primitives (spheres + triangles) up; below it,
// testing everything is as fast on lavapipe (measured: docs/performance.md).
constexpr std::size_t kBvhAutoThreshold = 16;

inline bool useHierarchy(Acceleration acceleration, std::size_t primitives) {
    if (acceleration == Acceleration::Auto) return primitives >= kBvhAutoThreshold;
    return acceleration == Acceleration::Bvh && primitives > 0;
}

struct BvhSettings {
    // Measured on lavapipe (docs/performance.md): leaves of up to 8 with a node visit costing two
    // primitive tests render as fast as smaller leaves or a cost of 1, with a third fewer nodes.
    std::uint32_t maxLeafSize = 8;           // a range at most this big may become a leaf
    std::uint32_t maxDepth = BVH_STACK_SIZE; // no leaf deeper (root at depth 0)
    float traversalCost = 2.0f; // cost of visiting a node (two box tests), in primitive tests
    // Above 1, the top levels' nodes are split at once, then the subtrees below them built
    // as tasks on that many threads; 0: workerThreads() (base/parallel.h). The tree is the
    // same for every count.
    std::uint32_t threads = 0;
};

struct Bvh {
    std::vector<gpu::GpuBvhNode> nodes; // interior nodes, depth first; node 0 is the root
    // Leaf order: slot k of the packed sphere (triangle) array holds the sphere (triangle)
    // that was number sphereOrder[k] (triangleOrder[k]) in the input. Leaves index slots.
    std::vector<std::uint32_t> sphereOrder;
    std::vector<std::uint32_t> triangleOrder;
    std::uint32_t depth = 0; // of the deepest leaf (a root that is a leaf: 0)
};

// Builds the hierarchy. Every primitive ends in exactly one leaf; every leaf holds one
// kind and its slots are consecutive. An empty input gives an empty hierarchy. The bounds
// are taken by value, so that a caller who moves them in frees their boxes during the build.
Bvh buildBvh(PrimitiveBounds bounds, const BvhSettings& settings = {});
