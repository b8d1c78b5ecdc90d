// The hierarchy builder (host/bvh.cpp) and the packer's leaf order, without a GPU: the
// tree is well formed, covers every primitive once, bounds what it holds, respects the
// traversal stack's depth limit on adversarial input, and splits where SAH should.
#include "bvh.h"
#include "scene_gpu.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>

namespace {

struct Box3 {
    glm::vec3 lo, hi;
};

Box3 nodeBox(const gpu::GpuBvhNode& node) {
    return {glm::vec3(node.boundsMinAndIndex), glm::vec3(node.boundsMaxAndCount)};
}

Box3 inputBox(const PrimitiveBounds& bounds, std::uint32_t id) {
    const float* b = bounds.boxes.data() + 6 * std::size_t(id);
    return {{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
}

bool contains(const Box3& outer, const Box3& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
           glm::all(glm::lessThanEqual(inner.hi, outer.hi));
}

void addBox(PrimitiveBounds& bounds, glm::vec3 lo, glm::vec3 hi) {
    bounds.boxes.insert(bounds.boxes.end(), {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
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

// What a walk from the root finds, checking the layout on the way: every node reached
// exactly once, left child next, right child after the left subtree.
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
    // Returns the index just past the subtree, so the layout can be checked.
    std::function<std::uint32_t(std::uint32_t, std::uint32_t)> visit = [&](std::uint32_t index,
                                                                           std::uint32_t depth) {
        EXPECT_LT(index, bvh.nodes.size());
        if (index >= bvh.nodes.size()) return index;
        ++visits[index];
        const gpu::GpuBvhNode& node = bvh.nodes[index];
        walk.depth = std::max(walk.depth, depth);
        if (isLeaf(node)) {
            ++walk.leaves;
            std::vector<int>& hits =
                holdsSpheres(node) ? walk.sphereSlotHits : walk.triangleSlotHits;
            const std::vector<std::uint32_t>& order =
                holdsSpheres(node) ? bvh.sphereOrder : bvh.triangleOrder;
            const std::uint32_t idBase = holdsSpheres(node) ? 0 : input.sphereCount;
            EXPECT_GT(primitiveCount(node), 0u);
            for (std::uint32_t slot = firstPrimitive(node);
                 slot < firstPrimitive(node) + primitiveCount(node); ++slot) {
                EXPECT_LT(slot, hits.size());
                if (slot >= hits.size()) break;
                ++hits[slot];
                EXPECT_TRUE(contains(nodeBox(node), inputBox(input, order[slot] + idBase)))
                    << "leaf " << index << " does not contain its primitive in slot " << slot;
            }
            return index + 1;
        }
        const std::uint32_t left = index + 1, right = rightChild(node);
        EXPECT_TRUE(contains(nodeBox(node), nodeBox(bvh.nodes[left]))) << "node " << index;
        EXPECT_TRUE(right < bvh.nodes.size() && contains(nodeBox(node), nodeBox(bvh.nodes[right])))
            << "node " << index;
        const std::uint32_t afterLeft = visit(left, depth + 1);
        EXPECT_EQ(afterLeft, right)
            << "the right child of node " << index << " does not follow its left subtree";
        return visit(right, depth + 1);
    };
    if (!bvh.nodes.empty()) {
        EXPECT_EQ(visit(0, 0), bvh.nodes.size());
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

TEST(Bvh, EveryPrimitiveInExactlyOneLeafAndEveryBoxBoundsItsContents) {
    PrimitiveBounds input = randomScene(300, 5000);
    Bvh bvh = buildBvh(input);
    expectWellFormed(bvh, input);
    Walk walk = walkTree(bvh, input);
    EXPECT_GE(walk.leaves, 5300 / BvhSettings{}.maxLeafSize); // no leaf above maxLeafSize
    EXPECT_EQ(bvh.nodes.size(), 2 * walk.leaves - 1);         // a binary tree
}

TEST(Bvh, LeavesStayWithinTheLeafSizeUnlessForced) {
    PrimitiveBounds input = randomScene(0, 2000);
    for (std::uint32_t maxLeafSize : {1u, 4u, 8u}) {
        BvhSettings settings;
        settings.maxLeafSize = maxLeafSize;
        Bvh bvh = buildBvh(input, settings);
        expectWellFormed(bvh, input, settings);
        for (const gpu::GpuBvhNode& node : bvh.nodes)
            if (isLeaf(node)) {
                EXPECT_LE(primitiveCount(node), maxLeafSize);
            }
    }
}

TEST(Bvh, EmptyAndSingleInputs) {
    EXPECT_TRUE(buildBvh(PrimitiveBounds{}).nodes.empty());
    PrimitiveBounds one;
    addBox(one, glm::vec3(0), glm::vec3(1));
    Bvh bvh = buildBvh(one);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_TRUE(isLeaf(bvh.nodes[0]));
    EXPECT_EQ(primitiveCount(bvh.nodes[0]), 1u);
    EXPECT_FALSE(holdsSpheres(bvh.nodes[0]));
}

TEST(Bvh, MixedSmallRangeIsSplitIntoOneLeafPerKind) {
    PrimitiveBounds input;
    input.sphereCount = 1;
    addBox(input, glm::vec3(0), glm::vec3(1));       // a sphere
    addBox(input, glm::vec3(0.5f), glm::vec3(1.5f)); // a triangle overlapping it
    Bvh bvh = buildBvh(input);
    expectWellFormed(bvh, input);
    ASSERT_EQ(bvh.nodes.size(), 3u);
    EXPECT_TRUE(holdsSpheres(bvh.nodes[1]) != holdsSpheres(bvh.nodes[2]));
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
    ASSERT_FALSE(isLeaf(bvh.nodes[0]));
    Box3 left = nodeBox(bvh.nodes[1]), right = nodeBox(bvh.nodes[rightChild(bvh.nodes[0])]);
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
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(primitiveCount(bvh.nodes[0]), 4u);
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
    const PackedScene original = packScene(scene);
    PackedScene packed = original;
    const PrimitiveBounds bounds = primitiveBounds(packed);
    Bvh bvh = buildBvh(bounds);
    applyLeafOrder(packed, bvh);
    for (std::size_t slot = 0; slot < bvh.sphereOrder.size(); ++slot) {
        EXPECT_EQ(packed.spheres[slot], original.spheres[bvh.sphereOrder[slot]]);
        EXPECT_EQ(packed.sphereMaterials[slot], original.sphereMaterials[bvh.sphereOrder[slot]]);
    }
    for (std::size_t slot = 0; slot < bvh.triangleOrder.size(); ++slot)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(packed.triangleVertices[3 * slot + k],
                      original.triangleVertices[3 * bvh.triangleOrder[slot] + k]);
    EXPECT_EQ(packed.vertexPositions, original.vertexPositions); // vertices stay shared, untouched
    // The reordered scene's own boxes are inside the leaves that now index them.
    const PrimitiveBounds reordered = primitiveBounds(packed);
    for (const gpu::GpuBvhNode& node : bvh.nodes) {
        if (!isLeaf(node)) continue;
        for (std::uint32_t slot = firstPrimitive(node);
             slot < firstPrimitive(node) + primitiveCount(node); ++slot)
            EXPECT_TRUE(contains(nodeBox(node),
                                 inputBox(reordered, holdsSpheres(node) ? slot : 40 + slot)));
    }
}

TEST(LeafOrder, SphereBoxesHaveAMarginAndTriangleBoxesAreExact) {
    Scene scene;
    scene.spheres.push_back({glm::dvec3(1, 2, 3), 0.5, {}});
    scene.triangles.push_back({{vertexAt({0, 0, -1}), vertexAt({1, 0, -1}), vertexAt({0, 1, -1})}});
    PrimitiveBounds bounds = primitiveBounds(packScene(scene));
    ASSERT_EQ(bounds.size(), 2u);
    Box3 sphere = inputBox(bounds, 0), triangle = inputBox(bounds, 1);
    EXPECT_TRUE(contains(sphere, {glm::vec3(0.5f, 1.5f, 2.5f), glm::vec3(1.5f, 2.5f, 3.5f)}));
    EXPECT_LT(sphere.lo.x, 0.5f); // strictly: rounding in the sphere test must not escape
    EXPECT_EQ(triangle.lo, glm::vec3(0, 0, -1)); // edges in the box's faces
    EXPECT_EQ(triangle.hi, glm::vec3(1, 1, -1));
}

} // namespace
