// What a device holds (scene/scene_capacity.h): each path's limit, the one that reaches
// further, the allocation's cap, each triangle layout's, and the message at the boundary.
#include "scene/scene_capacity.h"

#include <gtest/gtest.h>

namespace {

// lavapipe's limits, for triangles as corners (--triangle-layout corners).
SceneCapacity lavapipe() {
    SceneCapacity capacity;
    capacity.device = "llvmpipe";
    capacity.maxTexelBufferElements = 1u << 27;
    capacity.maxStorageBufferRange = 1u << 27;
    capacity.maxMemoryAllocationSize = 1ull << 31;
    capacity.indexedAllowed = false;
    return capacity;
}

// Indexed triangles take a uvec4 a triangle in their largest array, one texel, in both
// precisions; auto (both layouts allowed) counts the one that holds more.
TEST(SceneCapacity, IndexedTrianglesHoldAThirdOfTheTexelsAndBytes) {
    SceneCapacity indexed = lavapipe();
    indexed.indexedAllowed = true;
    indexed.cornersAllowed = false;
    // lavapipe's 2 GiB allocation binds before its texel limit: one uvec4 less the slot.
    const std::uint64_t allocated = ((1ull << 31) - 16) / 16;
    EXPECT_EQ(triangleCapacity(indexed).triangles, allocated);
    EXPECT_EQ(triangleCapacity(indexed).limit, "maxMemoryAllocationSize of 2147483648 bytes (16 "
                                               "a triangle, indexed, in one allocation)");
    indexed.maxMemoryAllocationSize = 0;
    EXPECT_EQ(triangleCapacity(indexed).triangles, 1u << 27);
    EXPECT_EQ(triangleCapacity(indexed).limit,
              "maxTexelBufferElements of 134217728 (1 texel a triangle, indexed)");
    indexed.fp64 = true; // the indices are uints: still one texel
    EXPECT_EQ(triangleCapacity(indexed).triangles, 1u << 27);
    indexed.texelReads = false;
    EXPECT_EQ(triangleCapacity(indexed).triangles, (1u << 27) / 16);
    EXPECT_EQ(triangleCapacity(indexed).limit,
              "maxStorageBufferRange of 134217728 bytes (16 a triangle, indexed)");

    // Auto: indexed holds the more, in every limit.
    SceneCapacity either = lavapipe();
    either.indexedAllowed = true;
    EXPECT_EQ(triangleCapacity(either).triangles, allocated);
    either.texelReads = false;
    EXPECT_EQ(triangleCapacity(either).triangles, (1u << 27) / 16);
}

TEST(SceneCapacity, TheTexelViewReachesFurtherThanTheStorageRange) {
    const TriangleCapacity most = triangleCapacity(lavapipe());
    EXPECT_EQ(most.triangles, (1u << 27) / 3); // 44,739,242: 3 texels a triangle
    EXPECT_EQ(most.limit, "maxTexelBufferElements of 134217728 (3 texels a triangle)");
}

TEST(SceneCapacity, StorageReadsAndFp64AreBoundByTheStorageRange) {
    SceneCapacity storage = lavapipe();
    storage.texelReads = false;
    EXPECT_EQ(triangleCapacity(storage).triangles, (1u << 27) / 48);
    SceneCapacity fp64 = lavapipe();
    fp64.fp64 = true;
    fp64.alignment = 32;
    EXPECT_EQ(triangleCapacity(fp64).triangles, (1u << 27) / 96);
    EXPECT_EQ(triangleCapacity(fp64).limit, "maxStorageBufferRange of 134217728 bytes (96 a "
                                            "triangle)");
}

TEST(SceneCapacity, OneAllocationCapsWhatAViewReaches) {
    SceneCapacity capacity = lavapipe();
    capacity.maxMemoryAllocationSize = 1u << 30; // 1 GiB: 22,369,621 triangles less the slot
    capacity.alignment = 64;
    const TriangleCapacity most = triangleCapacity(capacity);
    EXPECT_EQ(most.triangles, ((1u << 30) - 64) / 48);
    EXPECT_EQ(most.limit, "maxMemoryAllocationSize of 1073741824 bytes (48 a triangle, in one "
                          "allocation)");
    capacity.maxMemoryAllocationSize = 0; // not known: no cap of its own
    EXPECT_EQ(triangleCapacity(capacity).triangles, (1u << 27) / 3);
}

TEST(SceneCapacity, TheLargestSceneThatFitsPassesAndOneMoreIsRefused) {
    const SceneCapacity capacity = lavapipe();
    const std::uint64_t most = triangleCapacity(capacity).triangles;
    EXPECT_NO_THROW(checkTriangleCapacity(capacity, most, "lucy.obj"));
    try {
        checkTriangleCapacity(capacity, most + 1, "lucy.obj");
        ADD_FAILURE() << "one triangle too many passed";
    } catch (const CapacityError& error) {
        EXPECT_STREQ(error.what(),
                     "lucy.obj holds 44739243 triangles, more than llvmpipe can hold: its "
                     "maxTexelBufferElements of 134217728 (3 texels a triangle) sets the "
                     "largest scene at 44739242 triangles");
    }
}

} // namespace
