// Headless frames: trace, copy the output image to host memory, wait. No window system.
#pragma once

#include "image_io.h"
#include "renderer.h"

struct HeadlessTarget {
    Buffer readbackBuffer; // host-visible copy of the output image, tightly packed RGBA8
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence frameDone = VK_NULL_HANDLE;
};

void createHeadlessTarget(HeadlessTarget& target, const Context& context, const Renderer& renderer);

// Traces one frame and copies it to the readback buffer; returns the wall time from
// submit to fence in milliseconds.
double renderHeadlessFrame(HeadlessTarget& target, const Context& context, const Renderer& renderer);

// The last rendered frame as an image.
Image8 readHeadlessImage(const HeadlessTarget& target, const Renderer& renderer);

void destroyHeadlessTarget(HeadlessTarget& target, const Context& context);
