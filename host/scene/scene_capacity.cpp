#include "scene/scene_capacity.h"

#include <algorithm>

namespace {

constexpr std::uint64_t kCornersPerTriangle = 3;
constexpr std::uint64_t kCornerBytes = 16;   // vec4: position, packed word
constexpr std::uint64_t kCornerBytes64 = 32; // dvec4 in fp64

// The array bytes one buffer of maxBytes holds after its zeroed slot, as scene_upload.cpp
// lays them out: the slot and the array each rounded up to the alignment.
std::uint64_t arrayRoom(std::uint64_t maxBytes, std::uint64_t alignment) {
    const std::uint64_t usable = maxBytes / alignment * alignment;
    return usable > alignment ? usable - alignment : 0;
}

} // namespace

TriangleCapacity triangleCapacity(const SceneCapacity& capacity) {
    const std::uint64_t bytesPerTriangle =
        kCornersPerTriangle * (capacity.fp64 ? kCornerBytes64 : kCornerBytes);
    // The corners are bound whole as a storage buffer, or (fp32) read through a texel view
    // alone when they are beyond the storage range: the path that reaches further counts.
    TriangleCapacity best{capacity.maxStorageBufferRange / bytesPerTriangle,
                          "maxStorageBufferRange of " +
                              std::to_string(capacity.maxStorageBufferRange) + " bytes (" +
                              std::to_string(bytesPerTriangle) + " a triangle)"};
    if (capacity.texelReads && !capacity.fp64) {
        const std::uint64_t texels = capacity.maxTexelBufferElements / kCornersPerTriangle;
        if (texels > best.triangles)
            best = {texels, "maxTexelBufferElements of " +
                                std::to_string(capacity.maxTexelBufferElements) + " (" +
                                std::to_string(kCornersPerTriangle) + " texels a triangle)"};
    }
    if (capacity.maxMemoryAllocationSize) {
        const std::uint64_t allocated = arrayRoom(capacity.maxMemoryAllocationSize,
                                                  std::max<std::uint64_t>(capacity.alignment, 1)) /
                                        bytesPerTriangle;
        if (allocated < best.triangles)
            best = {allocated, "maxMemoryAllocationSize of " +
                                   std::to_string(capacity.maxMemoryAllocationSize) + " bytes (" +
                                   std::to_string(bytesPerTriangle) +
                                   " a triangle, in one allocation)"};
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
