// What a device can hold of a scene (scene/scene_capacity.h), read off its limits as the
// scene upload will meet them (render/scene_upload.h).
#pragma once

#include "gpu/context.h"
#include "scene/scene_capacity.h"

// Where each scene array starts in its buffer: a dvec4 array needs 32-byte alignment, and
// each range may also be a texel buffer's.
VkDeviceSize sceneArrayAlignment(const VkPhysicalDeviceLimits& limits, bool fp64);

// texelReads: the kernel may read arrays through texel views (not --storage-reads);
// fp64: --precision fp64.
SceneCapacity sceneCapacityOf(const Context& context, bool texelReads, bool fp64);

// The capacity of the device deviceRequest names (createDevice's choice, without a
// surface), from an instance made and destroyed for the question: what a scene will meet
// before it is read.
SceneCapacity probeSceneCapacity(const std::string& deviceRequest, bool texelReads, bool fp64);
