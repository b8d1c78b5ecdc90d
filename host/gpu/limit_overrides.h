// Device limits lowered below the device's own, for the tests (the hidden options
// --max-storage-range, --max-allocation and --max-image-side): a scene or an image that
// exceeds a lowered limit takes the same path as a large one under the real limit.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

struct LimitOverrides {
    VkDeviceSize maxStorageBufferRange = 0;   // 0: the device's
    VkDeviceSize maxMemoryAllocationSize = 0; // 0: the device's
    std::uint32_t maxImageDimension2D = 0;    // 0: the device's
};

// Applied by createDevice to the context's limits, each only where it is lower.
void setLimitOverrides(const LimitOverrides& overrides);
const LimitOverrides& limitOverrides();
