// The one error path for Vulkan calls: a failed call throws VulkanError whose
// message names the call, the VkResult and the source location.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <stdexcept>
#include <string>

struct VulkanError : std::runtime_error {
    VulkanError(VkResult failedResult, const std::string& message)
        : std::runtime_error(message), result(failedResult) {}
    VkResult result;
};

// "VK_ERROR_DEVICE_LOST" and so on (Debian's headers lack vk_enum_string_helper.h).
const char* vkResultName(VkResult result);

[[noreturn]] void throwVulkanError(VkResult result, const char* call, const char* file, int line);

// Test hook: with n > 0, the nth VK_CHECK from now skips its call and fails with
// VK_ERROR_OUT_OF_DEVICE_MEMORY, as a driver out of memory would; 0 turns it off. Lets a
// test fail each step of a creation in turn and look for leaks.
void failNthVulkanCheck(std::uint32_t n);

// Consulted by VK_CHECK: true once, for the check that failNthVulkanCheck chose.
bool vulkanCheckFailureInjected();

// Checks a VkResult-returning call; anything but VK_SUCCESS throws.
#define VK_CHECK(call)                                                                             \
    do {                                                                                           \
        VkResult vkCheckResult =                                                                   \
            vulkanCheckFailureInjected() ? VK_ERROR_OUT_OF_DEVICE_MEMORY : (call);                 \
        if (vkCheckResult != VK_SUCCESS)                                                           \
            throwVulkanError(vkCheckResult, #call, __FILE__, __LINE__);                            \
    } while (0)
