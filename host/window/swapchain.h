// Presentation: the swapchain on the window's surface. The trace is blitted into
// its images, so they are transfer destinations; the overlay draws over them as colour
// attachments; never storage images.
#pragma once

#include "gpu/context.h"

#include <vector>

struct Swapchain {
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED; // a UNORM format: the window shows the PNG's bytes
    VkExtent2D extent{};
    VkPresentModeKHR presentMode = VK_PRESENT_MODE_FIFO_KHR;
    std::vector<VkImage> images;
    // One per image: signalled by the submit that draws the image, waited on by its
    // present. Per image, not per frame in flight, because only re-acquiring the image
    // proves that the present which waited on the semaphore is done with it.
    std::vector<VkSemaphore> renderFinished;
};

// Creates the swapchain at framebufferSize, clamped to what the surface allows. vsync
// picks FIFO (always there); without it MAILBOX, else IMMEDIATE, else FIFO after all.
// Returns false, creating nothing, when the surface is 0x0 (a minimised window).
bool createSwapchain(Swapchain& swapchain, const Context& context, VkSurfaceKHR surface,
                     VkExtent2D framebufferSize, bool vsync = true);

// Replaces the swapchain after a resize or an OUT_OF_DATE/SUBOPTIMAL result, handing
// the old one to the driver as oldSwapchain. Waits for the device to be idle first.
// Returns false, leaving no swapchain, when the surface is 0x0.
bool recreateSwapchain(Swapchain& swapchain, const Context& context, VkSurfaceKHR surface,
                       VkExtent2D framebufferSize, bool vsync = true);

// "FIFO", "MAILBOX", "IMMEDIATE" or "FIFO_RELAXED", for messages.
const char* presentModeName(VkPresentModeKHR mode);

void destroySwapchain(Swapchain& swapchain, const Context& context);
