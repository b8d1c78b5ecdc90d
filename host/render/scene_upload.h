// The packed scene in one device buffer, each binding seeing its own range.
#pragma once

#include "gpu/resources.h"
#include "render/scene_packing.h"

// All scene arrays live in one device buffer; each binding sees its own range.
struct GpuScene {
    Buffer buffer;
    VkDescriptorBufferInfo ranges[BINDING_COUNT]{}; // BINDING_OUTPUT_IMAGE's entry unused
    VkDeviceSize bytes = 0;                         // device memory holding the scene
    std::uint32_t sphereCount = 0;
    std::uint32_t triangleCount = 0;
    std::uint32_t lightCount = 0;
    std::uint32_t bvhNodeCount = 0; // 0: no hierarchy
    glm::vec4 ambient{0.0f};
};

// Throws with the limit's name when an array exceeds maxStorageBufferRange.
GpuScene uploadScene(const Context& context, const PackedScene& packed);

void destroyGpuScene(const Context& context, GpuScene& scene);
