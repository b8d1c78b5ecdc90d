// Checks made before any work: an output image the device cannot hold fails up front
// with the limit's name and the device's, instead of an allocation error mid-way.
#pragma once

#include "gpu/context.h"

#include <cstdint>
#include <string>

// What bounds the output image (a storage image) and its host readback buffer.
struct ImageLimits {
    std::string deviceName;
    std::uint32_t maxImageDimension2D = 0;
    VkDeviceSize maxMemoryAllocationSize = 0; // VkPhysicalDeviceMaintenance3Properties
    VkDeviceSize largestDeviceLocalHeap = 0;
    VkDeviceSize largestHostVisibleHeap = 0; // a heap with a host-visible memory type
};

ImageLimits imageLimitsOf(const Context& context);

// Throws std::runtime_error naming the limit and the device when a width x height
// RGBA8 image (and, with readback, a host buffer of the same size) cannot be made.
void checkImageFits(const ImageLimits& limits, std::uint32_t width, std::uint32_t height,
                    bool readback);
