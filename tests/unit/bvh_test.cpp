// The hierarchy builder (host/packing/bvh.cpp) and the packer's leaf order, without a GPU: the
// tree is well formed in the two-wide layout of shared.h (child references round-trip,
// leaves in their parent's reference), covers every primitive once, bounds what it holds,
// numbers leaves in depth-first order, respects the traversal stack's depth limit on
// adversarial input, and splits where SAH should.
#include "packing/bvh.h"
#include "packing/scene_packing.h"

#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <numeric>

namespace {

struct Box3 {
    glm::vec3 lo, hi;
};

constexpr BvhSide kSides[] = {BvhSide::Left, BvhSide::Right};

Box3 childBox(const BvhChild& child) {
    return {child.lo, child.hi};
}

Box3 childBox(const gpu::GpuBvhNode& node, BvhSide side) {
    return childBox(bvhChild(node, side));
}

// The leaf children of every node, in array order.
std::vector<BvhChild> leafChildren(const Bvh& bvh) {
    std::vector<BvhChild> leaves;
    for (const gpu::GpuBvhNode& node : bvh.nodes)
        for (BvhSide side : kSides)
            if (bvhChild(node, side).leaf) leaves.push_back(bvhChild(node, side));
    return leaves;
}

// A hierarchy that is one leaf: one node, the leaf on the left and an empty leaf on the right.
bool isLoneLeaf(const Bvh& bvh) {
    return bvh.nodes.size() == 1 && bvhChild(bvh.nodes[0], BvhSide::Left).leaf &&
           bvhChild(bvh.nodes[0], BvhSide::Right).leaf &&
           bvhChild(bvh.nodes[0], BvhSide::Right).count == 0;
}

Box3 inputBox(const PrimitiveBounds& bounds, std::uint32_t id) {
    const PrimitiveBox& b = bounds.boxes[id];
    return {{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
}

bool contains(const Box3& outer, const Box3& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
           glm::all(glm::lessThanEqual(inner.hi, outer.hi));
}

void addBox(PrimitiveBounds& bounds, glm::vec3 lo, glm::vec3 hi) {
    bounds.boxes.push_back({{lo.x, lo.y, lo.z}, 0, {hi.x, hi.y, hi.z}, 0.0f});
}

// Deterministic pseudo-random numbers in [0, 1) (a 32-bit LCG; no seeding from the clock).
struct Random {
    std::uint32_t state = 12345;
    float next() {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / 16777216.0f;
    }
    glm::vec3 point(float scale) { return scale * glm::vec3(next(), next(), next()); }
};

// spheres random spheres then triangles random small triangles in a 100-unit cube.
PrimitiveBounds randomScene(std::uint32_t spheres, std::uint32_t triangles) {
    Random random;
    PrimitiveBounds bounds;
    bounds.sphereCount = spheres;
    for (std::uint32_t i = 0; i < spheres; ++i) {
        glm::vec3 c = random.point(100.0f);
        float r = 0.1f + 2.0f * random.next();
        addBox(bounds, c - r, c + r);
    }
    for (std::uint32_t i = 0; i < triangles; ++i) {
        glm::vec3 a = random.point(100.0f), b = a + random.point(3.0f), c = a + random.point(3.0f);
        addBox(bounds, glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
    }
    return bounds;
}

Box3 grown(const Box3& a, const Box3& b) {
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

constexpr Box3 kNothing{glm::vec3(INFINITY), glm::vec3(-INFINITY)};

// What a walk from the root finds, checking the layout on the way: every node reached
// exactly once, an interior left child next, an interior right child after the left
// subtree, every child box around its whole subtree, and leaves numbered in depth-first
// order (each kind's slots handed out leaf by leaf, as the tie rule of bvh.glsl expects).
struct Walk {
    std::uint32_t depth = 0;
    std::uint32_t leaves = 0;
    std::vector<int> sphereSlotHits, triangleSlotHits;
};

Walk walkTree(const Bvh& bvh, const PrimitiveBounds& input) {
    Walk walk;
    walk.sphereSlotHits.assign(bvh.sphereOrder.size(), 0);
    walk.triangleSlotHits.assign(bvh.triangleOrder.size(), 0);
    std::vector<int> visits(bvh.nodes.size(), 0);
    std::uint32_t nextSlot[2] = {0, 0}; // triangles, spheres
    auto visitLeaf = [&](const BvhChild& leaf, std::uint32_t depth) {
        Box3 bounds = kNothing;
        ++walk.leaves;
        walk.depth = std::max(walk.depth, depth);
        std::vector<int>& hits = leaf.spheres ? walk.sphereSlotHits : walk.triangleSlotHits;
        const std::vector<std::uint32_t>& order =
            leaf.spheres ? bvh.sphereOrder : bvh.triangleOrder;
        const std::uint32_t idBase = leaf.spheres ? 0 : input.sphereCount;
        EXPECT_EQ(leaf.index, nextSlot[leaf.spheres]) << "leaves out of depth-first order";
        nextSlot[leaf.spheres] = leaf.index + leaf.count;
        for (std::uint32_t slot = leaf.index; slot < leaf.index + leaf.count; ++slot) {
            EXPECT_LT(slot, hits.size());
            if (slot >= hits.size()) break;
            ++hits[slot];
            bounds = grown(bounds, inputBox(input, order[slot] + idBase));
        }
        return bounds;
    };
    // Returns the index just past the subtree, so the layout can be checked, and the box
    // of the primitives below.
    std::function<std::uint32_t(std::uint32_t, std::uint32_t, Box3&)> visit =
        [&](std::uint32_t index, std::uint32_t depth, Box3& bounds) {
            EXPECT_LT(index, bvh.nodes.size());
            if (index >= bvh.nodes.size()) return index;
            ++visits[index];
            std::uint32_t next = index + 1;
            for (BvhSide side : kSides) {
                const BvhChild child = bvhChild(bvh.nodes[index], side);
                Box3 below = kNothing;
                if (child.leaf) {
                    EXPECT_GT(child.count, 0u) << "an empty leaf below node " << index;
                    below = visitLeaf(child, depth + 1);
                } else {
                    EXPECT_EQ(child.index, next)
                        << "node " << index << "'s " << (side == BvhSide::Left ? "left" : "right")
                        << " child is not where depth-first order puts it";
                    next = visit(child.index, depth + 1, below);
                }
                EXPECT_TRUE(contains(childBox(child), below))
                    << "a child box of node " << index << " does not bound its subtree";
                bounds = grown(bounds, below);
            }
            return next;
        };
    if (isLoneLeaf(bvh)) {
        ++visits[0];
        const BvhChild leaf = bvhChild(bvh.nodes[0], BvhSide::Left);
        EXPECT_TRUE(contains(childBox(leaf), visitLeaf(leaf, 0)));
    } else if (!bvh.nodes.empty()) {
        Box3 bounds = kNothing;
        EXPECT_EQ(visit(0, 0, bounds), bvh.nodes.size());
    }
    for (std::size_t i = 0; i < visits.size(); ++i)
        EXPECT_EQ(visits[i], 1) << "node " << i;
    return walk;
}

bool isPermutation(std::vector<std::uint32_t> values) {
    std::sort(values.begin(), values.end());
    for (std::uint32_t i = 0; i < values.size(); ++i)
        if (values[i] != i) return false;
    return true;
}

void expectWellFormed(const Bvh& bvh, const PrimitiveBounds& input,
                      const BvhSettings& settings = {}) {
    ASSERT_EQ(bvh.sphereOrder.size(), input.sphereCount);
    ASSERT_EQ(bvh.triangleOrder.size(), input.size() - input.sphereCount);
    EXPECT_TRUE(isPermutation(bvh.sphereOrder));
    EXPECT_TRUE(isPermutation(bvh.triangleOrder));
    Walk walk = walkTree(bvh, input);
    for (int hits : walk.sphereSlotHits)
        EXPECT_EQ(hits, 1);
    for (int hits : walk.triangleSlotHits)
        EXPECT_EQ(hits, 1);
    EXPECT_EQ(walk.depth, bvh.depth);
    EXPECT_LE(walk.depth, settings.maxDepth);
}

TEST(BvhNode, ChildReferencesRoundTripOnBothSides) {
    const BvhChild children[] = {
        {glm::vec3(-1, -2, -3), glm::vec3(4, 5, 6), false, 7, 0, false},      // interior
        {glm::vec3(0), glm::vec3(1), true, 123456, 8, true},                  // sphere leaf
        {glm::vec3(-0.5f), glm::vec3(0.25f), true, BVH_FIRST_MASK, 1, false}, // the last slot
        {glm::vec3(2), glm::vec3(3), true, 0, BVH_MAX_LEAF_COUNT, true},      // the largest count
        {glm::vec3(2), glm::vec3(2), true, 0, 0, false},                      // the empty leaf
        {glm::vec3(1), glm::vec3(2), false, BVH_LEAF - 1, 0, false},          // the last node
    };
    for (const BvhChild& left : children)
        for (const BvhChild& right : children) {
            gpu::GpuBvhNode node{};
            setBvhChild(node, BvhSide::Left, left);
            setBvhChild(node, BvhSide::Right, right);
            EXPECT_EQ(bvhChild(node, BvhSide::Left), left);
            EXPECT_EQ(bvhChild(node, BvhSide::Right), right);
        }
}

TEST(BvhNode, ReferenceIsWhatTheShaderReads) {
    gpu::GpuBvhNode node{};
    setBvhChild(node, BvhSide::Right, {glm::vec3(0), glm::vec3(1), true, 42, 5, true});
    setBvhChild(node, BvhSide::Left, {glm::vec3(0), glm::vec3(1), false, 3, 0, false});
    EXPECT_EQ(std::bit_cast<std::uint32_t>(node.rightMinAndRef.w),
              BVH_LEAF | BVH_LEAF_SPHERES | 5u << BVH_COUNT_SHIFT | 42u);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(node.leftMinAndRef.w), 3u); // interior: its index
    EXPECT_EQ(node.rightMax, glm::vec4(1, 1, 1, 0));                   // w unused
    EXPECT_EQ(node.leftMax.w, 0.0f);
    EXPECT_THROW(setBvhChild(node, BvhSide::Left,
                             {glm::vec3(0), glm::vec3(1), true, 0, BVH_MAX_LEAF_COUNT + 1, false}),
                 std::invalid_argument);
    EXPECT_THROW(setBvhChild(node, BvhSide::Left,
                             {glm::vec3(0), glm::vec3(1), true, BVH_FIRST_MASK + 1, 1, false}),
                 std::invalid_argument);
    EXPECT_THROW(
        setBvhChild(node, BvhSide::Left, {glm::vec3(0), glm::vec3(1), false, BVH_LEAF, 0, false}),
        std::invalid_argument);
}

TEST(BvhNode, LeavesLargerThanTheCountFieldAreRefused) {
    PrimitiveBounds bounds;
    bounds.boxes.assign(4, PrimitiveBox{{0.0f, 0.0f, 0.0f}, 0, {0.0f, 0.0f, 0.0f}, 0.0f});
    BvhSettings settings;
    settings.maxLeafSize = BVH_MAX_LEAF_COUNT + 1;
    EXPECT_THROW(buildBvh(bounds, settings), std::invalid_argument);
}

TEST(Bvh, EveryPrimitiveInExactlyOneLeafAndEveryBoxBoundsItsContents) {
    PrimitiveBounds input = randomScene(300, 5000);
    Bvh bvh = buildBvh(input);
    expectWellFormed(bvh, input);
    Walk walk = walkTree(bvh, input);
    EXPECT_GE(walk.leaves, 5300 / BvhSettings{}.maxLeafSize); // no leaf above maxLeafSize
    EXPECT_EQ(bvh.nodes.size(), walk.leaves - 1);             // a binary tree's interior nodes
}

TEST(Bvh, LeavesStayWithinTheLeafSizeUnlessForced) {
    PrimitiveBounds input = randomScene(0, 2000);
    for (std::uint32_t maxLeafSize : {1u, 4u, 8u}) {
        BvhSettings settings;
        settings.maxLeafSize = maxLeafSize;
        Bvh bvh = buildBvh(input, settings);
        expectWellFormed(bvh, input, settings);
        for (const BvhChild& leaf : leafChildren(bvh))
            EXPECT_LE(leaf.count, maxLeafSize);
    }
}

TEST(Bvh, EmptyAndSingleInputs) {
    EXPECT_TRUE(buildBvh(PrimitiveBounds{}).nodes.empty());
    PrimitiveBounds one;
    addBox(one, glm::vec3(0), glm::vec3(1));
    Bvh bvh = buildBvh(one);
    expectWellFormed(bvh, one);
    ASSERT_TRUE(isLoneLeaf(bvh)); // the shader starts at node 0, so the root leaf gets one
    const BvhChild leaf = bvhChild(bvh.nodes[0], BvhSide::Left);
    EXPECT_EQ(leaf.count, 1u);
    EXPECT_EQ(leaf.index, 0u);
    EXPECT_FALSE(leaf.spheres);
    EXPECT_EQ(bvh.depth, 0u);
    // The empty leaf beside it: a point box, so that rays hardly ever enter it.
    const BvhChild empty = bvhChild(bvh.nodes[0], BvhSide::Right);
    EXPECT_EQ(empty.lo, empty.hi);

    PrimitiveBounds sphere;
    sphere.sphereCount = 1;
    addBox(sphere, glm::vec3(0), glm::vec3(1));
    Bvh sphereBvh = buildBvh(sphere);
    ASSERT_TRUE(isLoneLeaf(sphereBvh));
    EXPECT_TRUE(bvhChild(sphereBvh.nodes[0], BvhSide::Left).spheres);
}

TEST(Bvh, MixedSmallRangeIsSplitIntoOneLeafPerKind) {
    PrimitiveBounds input;
    input.sphereCount = 1;
    addBox(input, glm::vec3(0), glm::vec3(1));       // a sphere
    addBox(input, glm::vec3(0.5f), glm::vec3(1.5f)); // a triangle overlapping it
    Bvh bvh = buildBvh(input);
    expectWellFormed(bvh, input);
    ASSERT_EQ(bvh.nodes.size(), 1u); // one node over two leaves, spheres first
    const BvhChild left = bvhChild(bvh.nodes[0], BvhSide::Left);
    const BvhChild right = bvhChild(bvh.nodes[0], BvhSide::Right);
    ASSERT_TRUE(left.leaf && right.leaf);
    EXPECT_TRUE(left.spheres);
    EXPECT_FALSE(right.spheres);
    EXPECT_EQ(left.count + right.count, 2u);
    EXPECT_EQ(bvh.depth, 1u);
}

TEST(Bvh, IdenticalTrianglesStayWithinTheStackDepth) {
    PrimitiveBounds input;
    for (int i = 0; i < 10000; ++i)
        addBox(input, glm::vec3(-1, -1, -5), glm::vec3(1, 1, -5));
    Bvh bvh = buildBvh(input);
    expectWellFormed(bvh, input);
    // Balanced: halving 10000 down to leaves of 8 takes ceil(log2(1250)) = 11 levels.
    EXPECT_LE(bvh.depth, 11u);
}

TEST(Bvh, GeometricallySpacedPrimitivesStayWithinTheDepthLimit) {
    // Centroids at 2^i: each SAH split peels off only the few largest, so without the
    // median fallback the tree would be about as deep as the input is long.
    PrimitiveBounds input;
    for (int i = 0; i < 2000; ++i) {
        float x = std::ldexp(1.0f, i % 120 - 60) * (1.0f + float(i) / 4096.0f);
        addBox(input, glm::vec3(x, 0, 0), glm::vec3(x * 1.001f, 1, 1));
    }
    for (std::uint32_t maxDepth : {32u, 14u}) {
        BvhSettings settings;
        settings.maxDepth = maxDepth;
        Bvh bvh = buildBvh(input, settings);
        expectWellFormed(bvh, input, settings);
        EXPECT_LE(bvh.depth, maxDepth);
    }
    BvhSettings tooShallow;
    tooShallow.maxDepth =
        5; // 2000 primitives in leaves of 8 need 8 levels, and one to split by kind
    EXPECT_THROW(buildBvh(input, tooShallow), std::invalid_argument);
}

TEST(Bvh, SahSeparatesTwoClusters) {
    // 60 small boxes at x in [0, 1] and 20 at [100, 101]. An object-median split would
    // cut the big cluster (40 | 40); the cost function puts the plane in the gap.
    PrimitiveBounds input;
    Random random;
    for (int i = 0; i < 60; ++i) {
        glm::vec3 p = random.point(1.0f);
        addBox(input, p, p + 0.05f);
    }
    for (int i = 0; i < 20; ++i) {
        glm::vec3 p = glm::vec3(100, 0, 0) + random.point(1.0f);
        addBox(input, p, p + 0.05f);
    }
    Bvh bvh = buildBvh(input);
    expectWellFormed(bvh, input);
    ASSERT_FALSE(isLoneLeaf(bvh));
    Box3 left = childBox(bvh.nodes[0], BvhSide::Left),
         right = childBox(bvh.nodes[0], BvhSide::Right);
    if (left.lo.x > right.lo.x) std::swap(left, right);
    EXPECT_LT(left.hi.x, 2.0f) << "the low cluster's box reaches into the gap";
    EXPECT_GT(right.lo.x, 99.0f) << "the high cluster's box reaches into the gap";
}

TEST(Bvh, SahMakesALeafWhenSplittingDoesNotPay) {
    // Four boxes that all overlap almost entirely: splitting saves nothing.
    PrimitiveBounds input;
    for (int i = 0; i < 4; ++i)
        addBox(input, glm::vec3(0.001f * float(i)), glm::vec3(1.0f + 0.001f * float(i)));
    Bvh bvh = buildBvh(input);
    ASSERT_TRUE(isLoneLeaf(bvh));
    EXPECT_EQ(bvhChild(bvh.nodes[0], BvhSide::Left).count, 4u);
}

TEST(Bvh, TwoHundredThousandTrianglesBuild) {
    PrimitiveBounds input = randomScene(0, 200000);
    auto start = std::chrono::steady_clock::now();
    Bvh bvh = buildBvh(input);
    double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("200k triangles: %zu nodes, depth %u, built in %.1f ms\n", bvh.nodes.size(),
                bvh.depth, ms);
    expectWellFormed(bvh, input);
}

TEST(Bvh, TheTreeIsTheSameOnOneThreadAsOnSeveral) {
    // Large enough that the top levels are split at once and the rest built in tasks
    // (kSmallestTask in bvh.cpp), and that the root's passes and the slots' numbering run in
    // blocks (kParallelPass), with spheres in every block.
    const PrimitiveBounds input = randomScene(60000, 240000);
    BvhSettings one, four;
    one.threads = 1;
    four.threads = 4;
    const Bvh serial = buildBvh(input, one), parallel = buildBvh(input, four);
    ASSERT_EQ(serial.nodes.size(), parallel.nodes.size());
    EXPECT_EQ(std::memcmp(serial.nodes.data(), parallel.nodes.data(),
                          serial.nodes.size() * sizeof(gpu::GpuBvhNode)),
              0);
    EXPECT_EQ(serial.sphereOrder, parallel.sphereOrder);
    EXPECT_EQ(serial.triangleOrder, parallel.triangleOrder);
    EXPECT_EQ(serial.depth, parallel.depth);
}

Vertex vertexAt(glm::dvec3 position) {
    return {position, glm::dvec3(0, 0, 1), Material{glm::dvec3(0.5), glm::dvec3(0), 1}};
}

TEST(LeafOrder, KeepsEveryPrimitiveAndItsMaterialAndLeavesIndexTheReorderedArrays) {
    Scene scene;
    Random random;
    for (int i = 0; i < 40; ++i) {
        Material m{glm::dvec3(random.next()), glm::dvec3(0), 1};
        scene.spheres.push_back({glm::dvec3(random.point(20.0f)), 0.5, m});
    }
    for (int i = 0; i < 200; ++i) {
        glm::dvec3 a(random.point(20.0f));
        scene.triangles.push_back(
            {{vertexAt(a), vertexAt(a + glm::dvec3(1, 0, 0)), vertexAt(a + glm::dvec3(0, 1, 0))}});
    }
    const PackedScene original = packSceneInFileOrder(scene);
    PackedScene packed = original;
    const PrimitiveBounds bounds = primitiveBounds(packed);
    Bvh bvh = buildBvh(bounds);
    applyLeafOrder(packed, bvh);
    for (std::size_t slot = 0; slot < bvh.sphereOrder.size(); ++slot) {
        EXPECT_EQ(packed.spheres[slot], original.spheres[bvh.sphereOrder[slot]]);
        EXPECT_EQ(packed.sphereMaterials[slot], original.sphereMaterials[bvh.sphereOrder[slot]]);
    }
    for (std::size_t slot = 0; slot < bvh.triangleOrder.size(); ++slot)
        EXPECT_EQ(packed.triangles[slot], original.triangles[bvh.triangleOrder[slot]]);
    EXPECT_EQ(packed.vertexPositions, original.vertexPositions); // vertices stay shared, untouched
    // The reordered scene's own boxes are inside the leaves that now index them.
    const PrimitiveBounds reordered = primitiveBounds(packed);
    for (const BvhChild& leaf : leafChildren(bvh))
        for (std::uint32_t slot = leaf.index; slot < leaf.index + leaf.count; ++slot)
            EXPECT_TRUE(
                contains(childBox(leaf), inputBox(reordered, leaf.spheres ? slot : 40 + slot)));
}

TEST(LeafOrder, SphereBoxesHaveAMarginAndTriangleBoxesAreExact) {
    Scene scene;
    scene.spheres.push_back({glm::dvec3(1, 2, 3), 0.5, {}});
    scene.triangles.push_back({{vertexAt({0, 0, -1}), vertexAt({1, 0, -1}), vertexAt({0, 1, -1})}});
    PrimitiveBounds bounds = primitiveBounds(packSceneInFileOrder(scene));
    ASSERT_EQ(bounds.size(), 2u);
    Box3 sphere = inputBox(bounds, 0), triangle = inputBox(bounds, 1);
    EXPECT_TRUE(contains(sphere, {glm::vec3(0.5f, 1.5f, 2.5f), glm::vec3(1.5f, 2.5f, 3.5f)}));
    EXPECT_LT(sphere.lo.x, 0.5f); // strictly: rounding in the sphere test must not escape
    EXPECT_EQ(triangle.lo, glm::vec3(0, 0, -1)); // edges in the box's faces
    EXPECT_EQ(triangle.hi, glm::vec3(1, 1, -1));
}

} // namespace
