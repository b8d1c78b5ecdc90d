// Presentation: the frames in flight, the swapchain kept at the framebuffer's size, and
// one frame: trace the samples owed, blit the output image into a swapchain image, present.
// Samples per frame adapt to the frame time, and the title reports the progress.
#include "window/present.h"

#include "base/scope_guard.h"
#include "gpu/vk_check.h"
#include "window/capture.h"
#include "window/compare_view.h"
#include "window/overlay.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace {

// Samples per frame adapt to keep a frame between these (ms): quick to react to input,
// few enough frames that presenting does not dominate.
constexpr double kFastFrameMs = 20.0, kSlowFrameMs = 60.0;
constexpr std::uint32_t kMaxSamplesPerFrame = 64;

// Traces the next samples if any are owed, then blits the output image into the
// swapchain image.
void record(const Viewer& viewer, VkCommandBuffer commands, std::uint32_t imageIndex,
            SampleRange samples) {
    const VkImage target = viewer.swapchain.images[imageIndex];
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    // Without a trace the output image still holds the last one, in TRANSFER_SRC_OPTIMAL,
    // made visible to transfer reads by the barrier that ended that trace.
    if (samples.count > 0) recordTrace(viewer.renderer, commands, samples);

    // The swapchain image's old contents are discarded (UNDEFINED). The submit waits on
    // image-available at the TRANSFER stage, so this barrier, which starts at that stage,
    // orders the layout change and the blit's writes after the presentation engine let go.
    transitionImage(commands, target, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    // Same size, nearest filter: every pixel is copied unchanged. RGBA8 to BGRA8 UNORM
    // swaps channels only; the 8-bit values stay exact. With --compare, the image or the
    // difference may be shown instead (at its own size, stretched should the window differ).
    const Image* compared = comparedPicture(viewer);
    const Image& output = compared ? *compared : viewer.renderer.outputImage;
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {int32_t(output.width), int32_t(output.height), 1};
    region.dstSubresource = region.srcSubresource;
    region.dstOffsets[1] = {int32_t(viewer.swapchain.extent.width),
                            int32_t(viewer.swapchain.extent.height), 1};
    vkCmdBlitImage(commands, output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    // The overlay draws over the swapchain image only, after the blit; its render pass
    // hands the image to presentation.
    if (viewer.overlay.shown && viewer.overlay.created) {
        recordOverlay(viewer, commands, imageIndex);
        VK_CHECK(vkEndCommandBuffer(commands));
        return;
    }
    // Hand the image to presentation once the blit has written it. The present waits on
    // the render-finished semaphore, which makes the writes visible, so no access follows.
    transitionImage(commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    VK_CHECK(vkEndCommandBuffer(commands));
}

// "NAME - WxH - k/N spp - T ms - DEVICE": the tests wait for "k/N spp" with k == N.
void showTitle(const Viewer& viewer) {
    char title[512];
    std::snprintf(title, sizeof(title), "%s - %ux%u - %u/%u spp - %.1f ms - %s",
                  viewer.sceneName.c_str(), viewer.renderer.outputImage.width,
                  viewer.renderer.outputImage.height, viewer.samplesDone, viewer.sampleTarget,
                  viewer.lastFrameMs, viewer.context.properties.deviceName);
    glfwSetWindowTitle(viewer.window, title);
}

// The samples the next frame adds. The first frame of a view is the one-sample image, the
// pixel centre (as headless --spp 1), so that what the window shows after 1 sample is what
// 1 sample renders; the next frame starts the sum of the target's samples afresh, with at
// least 2 of them (samples 0..k-1 of an N-sample render are the k-sample render from k = 2:
// shaders/sampling.glsl). A frame stops at the next --snapshots count, so that the count is
// shown exactly.
SampleRange nextSamples(const Viewer& viewer) {
    if (viewer.samplesDone == 0 && viewer.sampleTarget > 1) return {0, 1, 1};
    std::uint32_t stop = viewer.sampleTarget;
    if (viewer.nextSnapshot < viewer.snapshotCounts.size())
        stop = std::min(stop, viewer.snapshotCounts[viewer.nextSnapshot]);
    // One sample shown of more is the first frame's centre, which the target's sum leaves out.
    const bool centreOnly = viewer.samplesDone == 1 && viewer.sampleTarget > 1;
    const std::uint32_t first = centreOnly ? 0 : viewer.samplesDone;
    std::uint32_t count = std::min(viewer.samplesPerFrame, stop - first);
    if (centreOnly) count = std::max(count, 2u);
    return {first, count};
}

// More samples per frame while frames are quick, fewer when slow. The bench keeps one.
void adaptSamplesPerFrame(Viewer& viewer, double milliseconds) {
    if (viewer.benchFrames > 0) return;
    if (milliseconds < kFastFrameMs)
        viewer.samplesPerFrame = std::min(viewer.samplesPerFrame * 2, kMaxSamplesPerFrame);
    else if (milliseconds > kSlowFrameMs)
        viewer.samplesPerFrame = std::max(viewer.samplesPerFrame / 2, 1u);
}

} // namespace

void createFrames(Viewer& viewer) {
    OnFailure release([&] { destroyFrames(viewer); });
    VkDevice device = viewer.context.device;
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT; // the first wait on each frame returns at once
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = viewer.context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    for (Frame& frame : viewer.frames) {
        VK_CHECK(vkAllocateCommandBuffers(device, &allocateInfo, &frame.commands));
        VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &frame.imageAvailable));
        VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &frame.done));
    }
}

void destroyFrames(Viewer& viewer) {
    VkDevice device = viewer.context.device;
    if (!device) return;
    for (Frame& frame : viewer.frames) {
        if (frame.done) vkDestroyFence(device, frame.done, nullptr);
        if (frame.imageAvailable) vkDestroySemaphore(device, frame.imageAvailable, nullptr);
        if (frame.commands)
            vkFreeCommandBuffers(device, viewer.context.commandPool, 1, &frame.commands);
        frame = Frame{};
    }
}

bool refreshSwapchain(Viewer& viewer) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(viewer.window, &width, &height);
    if (width <= 0 || height <= 0) return false;
    VkExtent2D size{std::uint32_t(width), std::uint32_t(height)};
    const VkPresentModeKHR oldMode = viewer.swapchain.presentMode;
    const bool existed = viewer.swapchain.swapchain != VK_NULL_HANDLE;
    bool created = existed ? recreateSwapchain(viewer.swapchain, viewer.context, viewer.surface,
                                               size, viewer.vsync)
                           : createSwapchain(viewer.swapchain, viewer.context, viewer.surface, size,
                                             viewer.vsync);
    if (!created) return false;
    if (existed && viewer.swapchain.presentMode != oldMode)
        std::fprintf(stderr, "Vsync %s (present mode %s)\n", viewer.vsync ? "on" : "off",
                     presentModeName(viewer.swapchain.presentMode));
    viewer.swapchainStale = false;
    viewer.presentNeeded = true;
    // The blit copies 1:1, so the output image always has the swapchain's size.
    const VkExtent2D extent = viewer.swapchain.extent;
    if (extent.width != viewer.renderer.outputImage.width ||
        extent.height != viewer.renderer.outputImage.height) {
        resizeOutput(viewer.renderer, viewer.context, extent.width, extent.height);
        restartRefinement(viewer);
    }
    // The overlay's render pass follows the swapchain's format, its framebuffers its images.
    if (viewer.overlay.created)
        overlaySwapchainChanged(viewer);
    else
        createOverlay(viewer);
    return true;
}

void drawFrame(Viewer& viewer) {
    // First: a switch changed in the panel rebuilds the renderer and restarts the sum.
    if (viewer.overlay.shown && viewer.overlay.created) buildOverlay(viewer);
    VkDevice device = viewer.context.device;
    Frame& frame = viewer.frames[viewer.frameIndex];
    VK_CHECK(vkWaitForFences(device, 1, &frame.done, VK_TRUE, UINT64_MAX));
    std::uint32_t imageIndex = 0;
    VkResult acquired = vkAcquireNextImageKHR(device, viewer.swapchain.swapchain, UINT64_MAX,
                                              frame.imageAvailable, VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        viewer.swapchainStale = true; // nothing was acquired, the semaphore stays unsignalled
        return;
    }
    if (acquired != VK_SUBOPTIMAL_KHR)
        VK_CHECK(acquired); // suboptimal still acquired an image: use it
    VK_CHECK(vkResetFences(device, 1, &frame.done));
    const SampleRange samples = refining(viewer) ? nextSamples(viewer) : SampleRange{};
    record(viewer, frame.commands, imageIndex, samples);

    VkSemaphore renderFinished = viewer.swapchain.renderFinished[imageIndex];
    VkPipelineStageFlags waitStage =
        VK_PIPELINE_STAGE_TRANSFER_BIT; // the first use of the image is the blit
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &frame.imageAvailable;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderFinished;
    const Clock::time_point submitted = Clock::now();
    resetKernelStatus(viewer.renderer);
    VK_CHECK(vkQueueSubmit(viewer.context.queue, 1, &submit, frame.done));

    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderFinished;
    present.swapchainCount = 1;
    present.pSwapchains = &viewer.swapchain.swapchain;
    present.pImageIndices = &imageIndex;
    VkResult presented = vkQueuePresentKHR(viewer.context.queue, &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
        acquired == VK_SUBOPTIMAL_KHR)
        viewer.swapchainStale = true; // presentNeeded stays set: show it again on the new swapchain
    else {
        VK_CHECK(presented);
        viewer.presentNeeded = false;
    }
    viewer.frameIndex = (viewer.frameIndex + 1) % kFramesInFlight;

    // A traced frame is waited for: it times the frame exactly (submit to fence), which
    // sizes the next one, and input is then never more than one frame behind.
    if (samples.count > 0) {
        VK_CHECK(vkWaitForFences(device, 1, &frame.done, VK_TRUE, UINT64_MAX));
        viewer.lastFrameMs =
            std::chrono::duration<double, std::milli>(Clock::now() - submitted).count();
        const std::uint32_t cutShort = cutShortInvocations(viewer.renderer);
        if (cutShort > 0 && !viewer.cutShortReported) {
            // The driver ended some invocations' loops early (GpuKernelStatus): the sum is
            // wrong. Fewer samples per dispatch, and the sum starts again for the same view
            // (a --snapshots series goes on: the counts it wrote were written right).
            if (traceFewerSamplesPerPass(viewer.renderer, viewer.context, samples.count)) {
                restartSum(viewer);
                viewer.presentNeeded = true;
                return;
            }
            viewer.cutShortReported = true;
            std::fprintf(stderr, "%s\n", cutShortWarning(cutShort).c_str());
        }
        viewer.samplesDone = samples.first + samples.count;
        if (viewer.nextSnapshot < viewer.snapshotCounts.size() &&
            viewer.samplesDone == viewer.snapshotCounts[viewer.nextSnapshot]) {
            viewer.snapshotNow = true; // written after this frame, as P's screenshot is
            ++viewer.nextSnapshot;
        }
        viewer.lastFrameSamples = samples.count;
        adaptSamplesPerFrame(viewer, viewer.lastFrameMs);
        // One line per finished image (the tests wait for it), none while soaking.
        if (!refining(viewer) && !viewer.continuous && viewer.benchFrames == 0)
            std::fprintf(stderr, "Refined: %u samples per pixel at %ux%u in %.2f s\n",
                         viewer.sampleTarget, viewer.renderer.outputImage.width,
                         viewer.renderer.outputImage.height,
                         std::chrono::duration<double>(Clock::now() - viewer.refineStart).count());
        showTitle(viewer);
        viewer.presentNeeded = viewer.presentNeeded || refining(viewer);
        countBenchFrame(viewer, samples.count);
    }
}
