// The Vulkan instance, the validation messenger, the chosen device and its one queue.
// A Context holds handles, not behaviour.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

struct Context {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE; // only with validation
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0; // graphics + compute (+ present when a window asked)
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    bool timestampsSupported = false;
    bool float64Enabled = false; // shaderFloat64 on, for --precision fp64 (createDevice)
    // The largest single allocation (VkPhysicalDeviceMaintenance3Properties): the scene is
    // placed in as many buffers as this takes (scene_upload.h).
    VkDeviceSize maxMemoryAllocationSize = 0;
};

// extensions: instance extensions the caller needs (GLFW's for a window).
// validate: enable VK_LAYER_KHRONOS_validation and count every message it prints.
void createInstance(Context& context, const std::vector<const char*>& extensions, bool validate);

// Chooses a device as createDevice does and reads its properties and limits (lowered by
// limit_overrides.h) into the context, without creating it: what a device can hold is known
// before a large scene is read (render/device_capacity.h).
void chooseDevice(Context& context, const std::string& deviceRequest,
                  VkSurfaceKHR surface = VK_NULL_HANDLE);

// Chooses a device: deviceRequest (a name substring or an index, as --device) when
// given, otherwise a discrete GPU before an integrated, virtual or CPU one. With a
// surface, only devices that can present to it qualify. Prints the choice to stderr.
// needFloat64 (--precision fp64) enables shaderFloat64, or fails before anything else
// is created when the chosen device lacks it (requireFloat64's message).
void createDevice(Context& context, const std::string& deviceRequest,
                  VkSurfaceKHR surface = VK_NULL_HANDLE, bool needFloat64 = false);

// Throws the message for --precision fp64 on a device without shaderFloat64.
void requireFloat64(const VkPhysicalDeviceFeatures& features, const char* deviceName);

void destroyContext(Context& context);

// How many messages the validation layer has printed so far (warnings and errors).
std::uint32_t validationMessageCount();

// A device type as people name it: "discrete GPU", "integrated GPU", "virtual GPU", "CPU",
// "other" (the device choice's messages; --list-devices prints it in lower case).
const char* deviceTypeName(VkPhysicalDeviceType type);
