// Device limits lowered below the device's own, for the tests (the hidden options
// --max-storage-range and --max-allocation): a scene that exceeds a lowered limit takes the
// same path as one that exceeds the real limit of a large scene, on a small scene.
#pragma once

#include <vulkan/vulkan.h>

struct LimitOverrides {
    VkDeviceSize maxStorageBufferRange = 0;   // 0: the device's
    VkDeviceSize maxMemoryAllocationSize = 0; // 0: the device's
};

// Applied by createDevice to the context's limits, each only where it is lower.
void setLimitOverrides(const LimitOverrides& overrides);
const LimitOverrides& limitOverrides();
