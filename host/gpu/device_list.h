// --list-devices: every Vulkan physical device the loader finds, with what this renderer
// depends on (double precision, and the limits on workgroups, images and buffers), in the
// order --device INDEX counts them.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

// One block per device, numbered as --device counts them; instance: any Vulkan 1.2 instance.
std::string deviceListing(VkInstance instance);

// The driver's version as its vendor encodes it (NVIDIA packs 10.8.8.6 bits, the others
// Vulkan's 10.10.12).
std::string driverVersionText(std::uint32_t vendorId, std::uint32_t version);
