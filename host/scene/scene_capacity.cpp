#include "scene/scene_capacity.h"

#include <algorithm>

namespace {

constexpr std::uint64_t kCornersPerTriangle = 3;
constexpr std::uint64_t kCornerBytes = 16;          // vec4: position, packed word
constexpr std::uint64_t kCornerBytes64 = 32;        // dvec4 in fp64
constexpr std::uint64_t kIndexedTriangleBytes = 16; // uvec4: vertex indices, flat patch

// The array bytes one buffer of maxBytes holds after its zeroed slot, as scene_upload.cpp
// lays them out: the slot and the array each rounded up to the alignment.
std::uint64_t arrayRoom(std::uint64_t maxBytes, std::uint64_t alignment) {
    const std::uint64_t usable = maxBytes / alignment * alignment;
    return usable > alignment ? usable - alignment : 0;
}

// The most triangles of one layout: bytesPerTriangle in the largest array, read through a
// texel view of texelsPerTriangle when texelReads (0: never).
TriangleCapacity layoutCapacity(const SceneCapacity& capacity, std::uint64_t bytesPerTriangle,
                                std::uint64_t texelsPerTriangle, const std::string& layout) {
    // The array is bound whole as a storage buffer, or read through its texel view alone
    // when it is beyond the storage range: the path that reaches further counts.
    TriangleCapacity best{capacity.maxStorageBufferRange / bytesPerTriangle,
                          "maxStorageBufferRange of " +
                              std::to_string(capacity.maxStorageBufferRange) + " bytes (" +
                              std::to_string(bytesPerTriangle) + " a triangle" + layout + ")"};
    if (capacity.texelReads && texelsPerTriangle) {
        const std::uint64_t texels = capacity.maxTexelBufferElements / texelsPerTriangle;
        const std::string each = texelsPerTriangle == 1 ? " texel" : " texels";
        if (texels > best.triangles)
            best = {texels, "maxTexelBufferElements of " +
                                std::to_string(capacity.maxTexelBufferElements) + " (" +
                                std::to_string(texelsPerTriangle) + each + " a triangle" + layout +
                                ")"};
    }
    if (capacity.maxMemoryAllocationSize) {
        const std::uint64_t allocated = arrayRoom(capacity.maxMemoryAllocationSize,
                                                  std::max<std::uint64_t>(capacity.alignment, 1)) /
                                        bytesPerTriangle;
        if (allocated < best.triangles)
            best = {allocated, "maxMemoryAllocationSize of " +
                                   std::to_string(capacity.maxMemoryAllocationSize) + " bytes (" +
                                   std::to_string(bytesPerTriangle) + " a triangle" + layout +
                                   ", in one allocation)"};
    }
    return best;
}

} // namespace

TriangleCapacity triangleCapacity(const SceneCapacity& capacity) {
    TriangleCapacity best;
    if (capacity.cornersAllowed)
        // fp64's doubles are read from storage alone.
        best = layoutCapacity(capacity,
                              kCornersPerTriangle * (capacity.fp64 ? kCornerBytes64 : kCornerBytes),
                              capacity.fp64 ? 0 : kCornersPerTriangle, "");
    if (capacity.indexedAllowed) {
        // A uvec4 of vertex indices, uints in both precisions.
        const TriangleCapacity indexed =
            layoutCapacity(capacity, kIndexedTriangleBytes, 1, ", indexed");
        if (indexed.triangles > best.triangles || !capacity.cornersAllowed) best = indexed;
    }
    return best;
}

void checkTriangleCapacity(const SceneCapacity& capacity, std::uint64_t triangles,
                           const std::string& fileName) {
    const TriangleCapacity most = triangleCapacity(capacity);
    if (triangles <= most.triangles) return;
    throw CapacityError(
        fileName + " holds " + std::to_string(triangles) + " triangles, more than " +
        capacity.device + " can hold: its " + most.limit + " sets the largest scene at " +
        std::to_string(most.triangles) + " triangles" + (capacity.fp64 ? " in fp64" : ""));
}
