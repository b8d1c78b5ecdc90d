// Presentation: per frame, trace the samples owed, blit the output image into a swapchain
// image and present it; the swapchain follows the framebuffer's size and the vsync choice.
#pragma once

#include "window/viewer.h"

// The frames in flight: a command buffer, an image-available semaphore and a fence each.
void createFrames(Viewer& viewer);
// Needs the device idle; harmless on frames never created.
void destroyFrames(Viewer& viewer);

// Makes a swapchain for the current framebuffer size and the output image to match.
// Returns false when the window is minimised (0x0): nothing to draw into.
bool refreshSwapchain(Viewer& viewer);

// Acquire, record, submit, present. A stale swapchain is only noted here; the loop
// recreates it and presents again.
void drawFrame(Viewer& viewer);
