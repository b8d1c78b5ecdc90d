// The overlay (Dear ImGui): a small panel over the window with the frame time, the samples
// so far, the rays per second and the device, live switches for the kernel's choices, and
// the camera as options. It is drawn in the present pass onto the swapchain image after
// the output image was blitted there, so the output image (what P writes and what
// headless renders) never holds it. H shows and hides it; --overlay opens it shown.
#pragma once

#include "window/viewer.h"

// ImGui's context, its GLFW backend (chained after installInputCallbacks' callbacks) and
// its Vulkan backend with a render pass for the swapchain's format. Needs the swapchain.
void createOverlay(Viewer& viewer);
// Needs the device idle; harmless on an overlay never created.
void destroyOverlay(Viewer& viewer);

// After the swapchain was made anew: framebuffers for its images (and a new render pass
// and pipeline should its format have changed).
void overlaySwapchainChanged(Viewer& viewer);

// Builds this frame's panel, applying a switch the user changed (the renderer is then
// rebuilt and refinement restarts). Call once per drawn frame, before recording.
void buildOverlay(Viewer& viewer);

// Records the panel over swapchain image imageIndex, which the blit left in
// TRANSFER_DST_OPTIMAL; leaves it in PRESENT_SRC_KHR.
void recordOverlay(const Viewer& viewer, VkCommandBuffer commands, std::uint32_t imageIndex);

// The mouse or keyboard is over or in the shown overlay: the camera leaves it alone.
bool overlayWantsMouse(const Viewer& viewer);
bool overlayWantsKeyboard(const Viewer& viewer);
