#include "render/device_capacity.h"

#include "base/scope_guard.h"

#include <algorithm>

VkDeviceSize sceneArrayAlignment(const VkPhysicalDeviceLimits& limits, bool fp64) {
    return std::max({VkDeviceSize(fp64 ? 32 : 16), limits.minStorageBufferOffsetAlignment,
                     limits.minTexelBufferOffsetAlignment});
}

SceneCapacity sceneCapacityOf(const Context& context, bool texelReads, bool fp64) {
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    SceneCapacity capacity;
    capacity.device = context.properties.deviceName;
    capacity.maxTexelBufferElements = limits.maxTexelBufferElements;
    capacity.maxStorageBufferRange = limits.maxStorageBufferRange;
    capacity.maxMemoryAllocationSize = context.maxMemoryAllocationSize;
    capacity.alignment = sceneArrayAlignment(limits, fp64);
    capacity.texelReads = texelReads;
    capacity.fp64 = fp64;
    return capacity;
}

SceneCapacity probeSceneCapacity(const std::string& deviceRequest, bool texelReads, bool fp64) {
    Context probe;
    ScopeExit close([&] { destroyContext(probe); });
    // No validation layer: the probe only queries, and its messages would come twice.
    createInstance(probe, {}, false);
    chooseDevice(probe, deviceRequest);
    return sceneCapacityOf(probe, texelReads, fp64);
}
