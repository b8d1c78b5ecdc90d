#include "window/swapchain.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace {

// A UNORM format in the sRGB colour space: the display then shows the stored bytes as
// they are, exactly like an image viewer shows the headless PNG. An _SRGB format would
// apply the sRGB curve a second time on write, so it is never taken.
VkSurfaceFormatKHR chooseFormat(const Context& context, VkSurfaceKHR surface) {
    std::uint32_t count = 0;
    VK_CHECK(
        vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice, surface, &count,
                                                  formats.data()));
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
        for (const VkSurfaceFormatKHR& format : formats) {
            if (format.format != wanted || format.colorSpace != VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                continue;
            VkFormatProperties properties{};
            vkGetPhysicalDeviceFormatProperties(context.physicalDevice, wanted, &properties);
            if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT) return format;
        }
    }
    throw std::runtime_error(
        std::string("the window surface on ") + context.properties.deviceName +
        " offers neither B8G8R8A8_UNORM nor R8G8B8A8_UNORM (sRGB colour space) "
        "as a blit destination; render headless with -o instead");
}

VkCompositeAlphaFlagBitsKHR chooseCompositeAlpha(VkCompositeAlphaFlagsKHR supported) {
    for (VkCompositeAlphaFlagBitsKHR mode :
         {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
          VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR})
        if (supported & mode) return mode;
    return VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
}

VkPresentModeKHR choosePresentMode(const Context& context, VkSurfaceKHR surface, bool vsync) {
    if (vsync) return VK_PRESENT_MODE_FIFO_KHR;
    std::uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice, surface, &count,
                                                       nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice, surface, &count,
                                                       modes.data()));
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
    return VK_PRESENT_MODE_FIFO_KHR;
}

// Creates the swapchain; oldSwapchain (may be null) is handed to the driver so it can
// reuse its resources. Returns false for a 0x0 surface.
bool create(Swapchain& swapchain, const Context& context, VkSurfaceKHR surface,
            VkExtent2D framebufferSize, VkSwapchainKHR oldSwapchain, bool vsync) {
    VkSurfaceCapabilitiesKHR capabilities{};
    VK_CHECK(
        vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context.physicalDevice, surface, &capabilities));
    if (!(capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw std::runtime_error(
            "the window surface does not accept transfer writes (blits) to its images");

    // 0xFFFFFFFF means the surface takes its size from the swapchain: use the framebuffer's.
    VkExtent2D extent = capabilities.currentExtent;
    if (extent.width == UINT32_MAX) extent = framebufferSize;
    extent.width = std::clamp(extent.width, capabilities.minImageExtent.width,
                              capabilities.maxImageExtent.width);
    extent.height = std::clamp(extent.height, capabilities.minImageExtent.height,
                               capabilities.maxImageExtent.height);
    if (extent.width == 0 || extent.height == 0) return false;

    std::uint32_t imageCount = capabilities.minImageCount + 1;
    if (capabilities.maxImageCount > 0)
        imageCount = std::min(imageCount, capabilities.maxImageCount);
    VkSurfaceFormatKHR format = chooseFormat(context, surface);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = imageCount;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    // Transfer writes for the blit; a colour attachment for the overlay drawn over it (every
    // surface supports that usage).
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE; // one queue family does everything
    info.preTransform = capabilities.currentTransform;
    info.compositeAlpha = chooseCompositeAlpha(capabilities.supportedCompositeAlpha);
    info.presentMode = choosePresentMode(context, surface, vsync);
    info.clipped = VK_TRUE;
    info.oldSwapchain = oldSwapchain;
    VK_CHECK(vkCreateSwapchainKHR(context.device, &info, nullptr, &swapchain.swapchain));
    swapchain.format = format.format;
    swapchain.extent = extent;
    swapchain.presentMode = info.presentMode;

    std::uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(context.device, swapchain.swapchain, &count, nullptr));
    swapchain.images.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(context.device, swapchain.swapchain, &count,
                                     swapchain.images.data()));
    swapchain.renderFinished.resize(count, VK_NULL_HANDLE);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (VkSemaphore& semaphore : swapchain.renderFinished)
        VK_CHECK(vkCreateSemaphore(context.device, &semaphoreInfo, nullptr, &semaphore));
    return true;
}

// Destroys the semaphores and forgets the images (the swapchain owns those).
void destroySemaphores(Swapchain& swapchain, const Context& context) {
    for (VkSemaphore semaphore : swapchain.renderFinished)
        if (semaphore) vkDestroySemaphore(context.device, semaphore, nullptr);
    swapchain.renderFinished.clear();
    swapchain.images.clear();
}

} // namespace

bool createSwapchain(Swapchain& swapchain, const Context& context, VkSurfaceKHR surface,
                     VkExtent2D framebufferSize, bool vsync) {
    OnFailure release([&] { destroySwapchain(swapchain, context); });
    return create(swapchain, context, surface, framebufferSize, VK_NULL_HANDLE, vsync);
}

bool recreateSwapchain(Swapchain& swapchain, const Context& context, VkSurfaceKHR surface,
                       VkExtent2D framebufferSize, bool vsync) {
    // Idle, so no submit still signals an old semaphore and no present still waits on one.
    VK_CHECK(vkDeviceWaitIdle(context.device));
    destroySemaphores(swapchain, context);
    VkSwapchainKHR old = swapchain.swapchain;
    swapchain = Swapchain{};
    // The old swapchain is retired by the create call (or unused when none was made).
    ScopeExit releaseOld([&] {
        if (old) vkDestroySwapchainKHR(context.device, old, nullptr);
    });
    OnFailure release([&] { destroySwapchain(swapchain, context); });
    return create(swapchain, context, surface, framebufferSize, old, vsync);
}

void destroySwapchain(Swapchain& swapchain, const Context& context) {
    if (!context.device) return;
    destroySemaphores(swapchain, context);
    if (swapchain.swapchain) vkDestroySwapchainKHR(context.device, swapchain.swapchain, nullptr);
    swapchain = Swapchain{};
}

const char* presentModeName(VkPresentModeKHR mode) {
    switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR:
        return "FIFO";
    case VK_PRESENT_MODE_MAILBOX_KHR:
        return "MAILBOX";
    case VK_PRESENT_MODE_IMMEDIATE_KHR:
        return "IMMEDIATE";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR:
        return "FIFO_RELAXED";
    default:
        return "other";
    }
}
