#include "gpu/device_list.h"

#include "gpu/context.h"
#include "gpu/vk_check.h"

#include <cctype>

#include <cstdint>
#include <vector>

namespace {

// "discrete gpu", "cpu", ...: the device choice's names in lower case.
std::string typeName(VkPhysicalDeviceType type) {
    std::string name = deviceTypeName(type);
    for (char& c : name)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return name;
}

std::string apiVersionText(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

// The driver's name and description; they are core from Vulkan 1.2 only.
std::string driverLines(VkPhysicalDevice device, const VkPhysicalDeviceProperties& properties) {
    const std::string version =
        "  driver version: " + driverVersionText(properties.vendorID, properties.driverVersion) +
        "\n";
    if (properties.apiVersion < VK_API_VERSION_1_2) return "  driver: unknown\n" + version;
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 both{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    both.pNext = &driver;
    vkGetPhysicalDeviceProperties2(device, &both);
    return std::string("  driver: ") + driver.driverName + "\n  driver info: " + driver.driverInfo +
           "\n" + version;
}

} // namespace

std::string driverVersionText(std::uint32_t vendorId, std::uint32_t version) {
    constexpr std::uint32_t kNvidia = 0x10DE;
    if (vendorId == kNvidia)
        return std::to_string(version >> 22) + "." + std::to_string((version >> 14) & 0xFF) + "." +
               std::to_string((version >> 6) & 0xFF) + "." + std::to_string(version & 0x3F);
    return std::to_string(version >> 22) + "." + std::to_string((version >> 12) & 0x3FF) + "." +
           std::to_string(version & 0xFFF);
}

std::string deviceListing(VkInstance instance) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    if (devices.empty())
        return "No Vulkan device found; install a driver, e.g. Debian's mesa-vulkan-drivers for "
               "lavapipe.\n";
    std::string text;
    for (std::size_t i = 0; i < devices.size(); ++i) {
        VkPhysicalDeviceProperties properties{};
        vkGetPhysicalDeviceProperties(devices[i], &properties);
        VkPhysicalDeviceFeatures features{};
        vkGetPhysicalDeviceFeatures(devices[i], &features);
        const VkPhysicalDeviceLimits& limits = properties.limits;
        text += "[" + std::to_string(i) + "] " + properties.deviceName + "\n";
        text += "  type: " + typeName(properties.deviceType) + "\n";
        text += driverLines(devices[i], properties);
        text += "  vulkan: " + apiVersionText(properties.apiVersion) + "\n";
        text += std::string("  fp64 (shaderFloat64): ") + (features.shaderFloat64 ? "yes" : "no") +
                "\n";
        text += "  maxComputeWorkGroupInvocations: " +
                std::to_string(limits.maxComputeWorkGroupInvocations) + "\n";
        text += "  maxImageDimension2D: " + std::to_string(limits.maxImageDimension2D) + "\n";
        text += "  maxTexelBufferElements: " + std::to_string(limits.maxTexelBufferElements) + "\n";
        text += "  maxStorageBufferRange: " + std::to_string(limits.maxStorageBufferRange) + "\n";
    }
    return text + "Choose one with --device INDEX (the number in brackets) or --device NAME (any "
                  "part of its name).\n";
}
