#include "gpu/vk_check.h"

#include <atomic>
#include <filesystem>

namespace {

std::atomic<std::uint32_t> checksUntilInjectedFailure{0}; // 0: no failure injected

} // namespace

void failNthVulkanCheck(std::uint32_t n) {
    checksUntilInjectedFailure = n;
}

bool vulkanCheckFailureInjected() {
    std::uint32_t left = checksUntilInjectedFailure.load(std::memory_order_relaxed);
    while (left > 0 && !checksUntilInjectedFailure.compare_exchange_weak(left, left - 1))
        ;
    return left == 1;
}

const char* vkResultName(VkResult result) {
    switch (result) {
#define RESULT_NAME(name)                                                                          \
    case name:                                                                                     \
        return #name;
        RESULT_NAME(VK_SUCCESS)
        RESULT_NAME(VK_NOT_READY)
        RESULT_NAME(VK_TIMEOUT)
        RESULT_NAME(VK_EVENT_SET)
        RESULT_NAME(VK_EVENT_RESET)
        RESULT_NAME(VK_INCOMPLETE)
        RESULT_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
        RESULT_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        RESULT_NAME(VK_ERROR_INITIALIZATION_FAILED)
        RESULT_NAME(VK_ERROR_DEVICE_LOST)
        RESULT_NAME(VK_ERROR_MEMORY_MAP_FAILED)
        RESULT_NAME(VK_ERROR_LAYER_NOT_PRESENT)
        RESULT_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
        RESULT_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
        RESULT_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
        RESULT_NAME(VK_ERROR_TOO_MANY_OBJECTS)
        RESULT_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
        RESULT_NAME(VK_ERROR_FRAGMENTED_POOL)
        RESULT_NAME(VK_ERROR_UNKNOWN)
        RESULT_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
        RESULT_NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        RESULT_NAME(VK_ERROR_FRAGMENTATION)
        RESULT_NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        RESULT_NAME(VK_PIPELINE_COMPILE_REQUIRED)
        RESULT_NAME(VK_ERROR_SURFACE_LOST_KHR)
        RESULT_NAME(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        RESULT_NAME(VK_SUBOPTIMAL_KHR)
        RESULT_NAME(VK_ERROR_OUT_OF_DATE_KHR)
        RESULT_NAME(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR)
        RESULT_NAME(VK_ERROR_VALIDATION_FAILED_EXT)
        RESULT_NAME(VK_ERROR_INVALID_SHADER_NV)
#undef RESULT_NAME
    default:
        return "unknown VkResult";
    }
}

void throwVulkanError(VkResult result, const char* call, const char* file, int line) {
    std::string where =
        std::filesystem::path(file).filename().string() + ":" + std::to_string(line);
    std::string message = std::string("Vulkan call failed with ") + vkResultName(result) + " (" +
                          std::to_string(result) + ") at " + where + ": " + call;
    if (result == VK_ERROR_DEVICE_LOST)
        message += "\n(the device was lost: a driver crash, a GPU reset or a watchdog timeout)";
    throw VulkanError(result, message);
}
