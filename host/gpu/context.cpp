#include "gpu/context.h"

#include "base/notes.h"
#include "gpu/cpu_driver.h"
#include "gpu/limit_overrides.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
std::atomic<std::uint32_t> validationMessages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void*) {
    const char* level =
        (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::fprintf(stderr, "validation %s: %s\n", level, data->pMessage);
    ++validationMessages;
    return VK_FALSE;
}

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& layer) {
        return !std::strcmp(layer.layerName, name);
    });
}

// Higher is better when no device is named.
int deviceTypeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 1;
    default:
        return 0;
    }
}

struct Candidate {
    VkPhysicalDevice device;
    VkPhysicalDeviceProperties properties;
    std::uint32_t queueFamily = 0;
    std::string rejection; // empty when usable
};

// A device qualifies when it is Vulkan 1.2+ and one queue family does graphics
// (for the blit to the window) and compute, and presents to the surface if any.
Candidate examine(VkPhysicalDevice device, VkSurfaceKHR surface) {
    Candidate candidate{device, {}, 0, {}};
    vkGetPhysicalDeviceProperties(device, &candidate.properties);
    if (candidate.properties.apiVersion < VK_API_VERSION_1_2) {
        candidate.rejection =
            "supports only Vulkan " +
            std::to_string(VK_API_VERSION_MAJOR(candidate.properties.apiVersion)) + "." +
            std::to_string(VK_API_VERSION_MINOR(candidate.properties.apiVersion)) +
            ", 1.2 is needed";
        return candidate;
    }
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i) {
        VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & needed) != needed) continue;
        if (surface) {
            VkBool32 presents = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &presents);
            if (!presents) continue;
        }
        candidate.queueFamily = i;
        return candidate;
    }
    candidate.rejection = surface ? "no queue family does graphics, compute and presentation"
                                  : "no queue family does both graphics and compute";
    return candidate;
}

std::string listCandidates(const std::vector<Candidate>& candidates) {
    std::string list;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const Candidate& c = candidates[i];
        list += "\n  [" + std::to_string(i) + "] " + c.properties.deviceName + " (" +
                deviceTypeName(c.properties.deviceType) + ")" +
                (c.rejection.empty() ? "" : ": rejected, " + c.rejection);
    }
    return list;
}

const Candidate& chooseCandidate(const std::vector<Candidate>& candidates,
                                 const std::string& request) {
    if (!request.empty()) {
        bool isIndex = std::all_of(request.begin(), request.end(), ::isdigit);
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            const Candidate& c = candidates[i];
            bool matches =
                isIndex ? std::to_string(i) == request
                        : std::string(c.properties.deviceName).find(request) != std::string::npos;
            if (!matches) continue;
            if (!c.rejection.empty())
                throw std::runtime_error("--device " + request + " names " +
                                         c.properties.deviceName +
                                         ", which cannot be used: " + c.rejection);
            return c;
        }
        throw std::runtime_error("--device " + request +
                                 " matches no Vulkan device. Found:" + listCandidates(candidates));
    }
    const Candidate* best = nullptr;
    for (const Candidate& c : candidates)
        if (c.rejection.empty() && (!best || deviceTypeRank(c.properties.deviceType) >
                                                 deviceTypeRank(best->properties.deviceType)))
            best = &c;
    if (!best)
        throw std::runtime_error("no usable Vulkan device. Found:" + listCandidates(candidates));
    return *best;
}

} // namespace

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "CPU";
    default:
        return "other";
    }
}

std::uint32_t validationMessageCount() {
    return validationMessages.load();
}

void createInstance(Context& context, const std::vector<const char*>& extensions, bool validate) {
    std::vector<const char*> enabledExtensions = extensions;
    std::vector<const char*> layers;
    if (validate) {
        if (!hasLayer(kValidationLayer))
            throw std::runtime_error(std::string("--validate needs ") + kValidationLayer +
                                     ", which is not installed (Debian: vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        enabledExtensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkApplicationInfo application{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    application.pApplicationName = "Raytracer";
    application.apiVersion = VK_API_VERSION_1_2;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = onValidationMessage;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &application;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(enabledExtensions.size());
    info.ppEnabledExtensionNames = enabledExtensions.data();
    // Chaining the messenger info also reports problems in vkCreate/DestroyInstance.
    if (validate) info.pNext = &messengerInfo;
    VkResult result = vkCreateInstance(&info, nullptr, &context.instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw std::runtime_error(
            "no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); "
            "install one, e.g. Debian's mesa-vulkan-drivers");
    VK_CHECK(result);

    if (validate) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(context.instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(context.instance, &messengerInfo, nullptr, &context.messenger));
        note("Validation: %s on; any message fails the run\n", kValidationLayer);
    }
}

void requireFloat64(const VkPhysicalDeviceFeatures& features, const char* deviceName) {
    if (!features.shaderFloat64)
        throw std::runtime_error(std::string("--precision fp64 needs the shaderFloat64 feature "
                                             "(double precision in shaders), which ") +
                                 deviceName +
                                 " does not have; use --precision fp32 (the default) or "
                                 "choose another device with --device");
}

void chooseDevice(Context& context, const std::string& deviceRequest, VkSurfaceKHR surface) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(context.instance, &count, devices.data()));
    if (devices.empty())
        throw std::runtime_error(
            "the Vulkan loader found no device; install a driver, e.g. Debian's "
            "mesa-vulkan-drivers for lavapipe");
    std::vector<Candidate> candidates;
    for (VkPhysicalDevice device : devices)
        candidates.push_back(examine(device, surface));
    const Candidate& chosen = chooseCandidate(candidates, deviceRequest);

    context.physicalDevice = chosen.device;
    context.properties = chosen.properties;
    VkPhysicalDeviceMaintenance3Properties maintenance3{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &maintenance3;
    vkGetPhysicalDeviceProperties2(chosen.device, &properties2);
    context.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
    const LimitOverrides& lowered = limitOverrides();
    std::uint32_t& storageRange = context.properties.limits.maxStorageBufferRange;
    if (lowered.maxStorageBufferRange && lowered.maxStorageBufferRange < storageRange)
        storageRange = static_cast<std::uint32_t>(lowered.maxStorageBufferRange);
    if (lowered.maxMemoryAllocationSize &&
        lowered.maxMemoryAllocationSize < context.maxMemoryAllocationSize)
        context.maxMemoryAllocationSize = lowered.maxMemoryAllocationSize;
    std::uint32_t& imageSide = context.properties.limits.maxImageDimension2D;
    if (lowered.maxImageDimension2D && lowered.maxImageDimension2D < imageSide)
        imageSide = lowered.maxImageDimension2D;
    context.queueFamily = chosen.queueFamily;
    vkGetPhysicalDeviceMemoryProperties(chosen.device, &context.memoryProperties);
}

void createDevice(Context& context, const std::string& deviceRequest, VkSurfaceKHR surface,
                  bool needFloat64) {
    chooseDevice(context, deviceRequest, surface);
    note("Device: %s (%s)\n", context.properties.deviceName,
         deviceTypeName(context.properties.deviceType));
    if (requestedCpuDriverThreads() > 0 &&
        context.properties.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU)
        note("note: --threads %u sets a CPU driver's threads; %s is not one\n",
             requestedCpuDriverThreads(), context.properties.deviceName);
    VkPhysicalDeviceFeatures enabledFeatures{};
    if (needFloat64) {
        VkPhysicalDeviceFeatures supported{};
        vkGetPhysicalDeviceFeatures(context.physicalDevice, &supported);
        requireFloat64(supported, context.properties.deviceName);
        enabledFeatures.shaderFloat64 = VK_TRUE;
    }

    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice, &familyCount, families.data());
    context.timestampsSupported = families[context.queueFamily].timestampValidBits > 0 &&
                                  context.properties.limits.timestampPeriod > 0;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = context.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    const char* swapchainExtension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.pEnabledFeatures = &enabledFeatures;
    if (surface) {
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &swapchainExtension;
    }
    VK_CHECK(vkCreateDevice(context.physicalDevice, &info, nullptr, &context.device));
    context.float64Enabled = needFloat64;
    vkGetDeviceQueue(context.device, context.queueFamily, 0, &context.queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = context.queueFamily;
    VK_CHECK(vkCreateCommandPool(context.device, &poolInfo, nullptr, &context.commandPool));
}

void destroyContext(Context& context) {
    if (context.device) {
        vkDeviceWaitIdle(context.device);
        if (context.commandPool) vkDestroyCommandPool(context.device, context.commandPool, nullptr);
        vkDestroyDevice(context.device, nullptr);
    }
    if (context.messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(context.instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(context.instance, context.messenger, nullptr);
    }
    if (context.instance) vkDestroyInstance(context.instance, nullptr);
    context = Context{};
}
