#include "gpu/image_limits.h"

#include <algorithm>
#include <stdexcept>

namespace {

std::string mebibytes(VkDeviceSize bytes) {
    return std::to_string(bytes >> 20) + " MiB";
}

} // namespace

ImageLimits imageLimitsOf(const Context& context) {
    ImageLimits limits;
    limits.deviceName = context.properties.deviceName;
    limits.maxImageDimension2D = context.properties.limits.maxImageDimension2D;
    limits.maxMemoryAllocationSize = context.maxMemoryAllocationSize;
    const VkPhysicalDeviceMemoryProperties& memory = context.memoryProperties;
    for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h)
        if (memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            limits.largestDeviceLocalHeap =
                std::max(limits.largestDeviceLocalHeap, memory.memoryHeaps[h].size);
    for (std::uint32_t t = 0; t < memory.memoryTypeCount; ++t)
        if (memory.memoryTypes[t].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
            limits.largestHostVisibleHeap =
                std::max(limits.largestHostVisibleHeap,
                         memory.memoryHeaps[memory.memoryTypes[t].heapIndex].size);
    return limits;
}

void checkImageFits(const ImageLimits& limits, std::uint32_t width, std::uint32_t height,
                    bool readback) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const std::string device = " (" + limits.deviceName + ")";
    if (width > limits.maxImageDimension2D || height > limits.maxImageDimension2D)
        throw std::runtime_error("a " + size +
                                 " image exceeds this device's maxImageDimension2D of " +
                                 std::to_string(limits.maxImageDimension2D) + device);
    const VkDeviceSize bytes = VkDeviceSize(width) * height * 4;
    const std::string needs = "a " + size + " image needs " + mebibytes(bytes);
    if (bytes > limits.maxMemoryAllocationSize)
        throw std::runtime_error(needs + ", more than this device's maxMemoryAllocationSize of " +
                                 mebibytes(limits.maxMemoryAllocationSize) + device);
    if (bytes > limits.largestDeviceLocalHeap)
        throw std::runtime_error(needs +
                                 ", more than this device's largest device-local memory heap of " +
                                 mebibytes(limits.largestDeviceLocalHeap) + device);
    if (readback && bytes > limits.largestHostVisibleHeap)
        throw std::runtime_error(needs +
                                 " of host-visible memory to read it back, more than this "
                                 "device's largest host-visible heap of " +
                                 mebibytes(limits.largestHostVisibleHeap) + device);
}
