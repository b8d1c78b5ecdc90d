#include "render/headless.h"

#include "base/notes.h"
#include "base/scope_guard.h"
#include "gpu/vk_check.h"
#include "render/interrupt.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Submits the recorded command buffer and waits for it; returns submit to fence in ms.
double submitAndTime(HeadlessTarget& target, const Context& context) {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &target.commands;
    const Clock::time_point start = Clock::now();
    VK_CHECK(vkQueueSubmit(context.queue, 1, &submit, target.submissionDone));
    VK_CHECK(vkWaitForFences(context.device, 1, &target.submissionDone, VK_TRUE, UINT64_MAX));
    const double milliseconds = millisecondsSince(start);
    VK_CHECK(vkResetFences(context.device, 1, &target.submissionDone));
    return milliseconds;
}

// Records the copy of the float averages (accumulation buffer) to the host buffer, after
// the kernel's writes, and makes them visible to the host after the fence.
void recordFloatCopyToHost(VkCommandBuffer commands, const Buffer& accumulation,
                           const Buffer& hostBuffer) {
    VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &written, 0, nullptr, 0, nullptr);
    const VkBufferCopy region{0, 0, hostBuffer.size};
    vkCmdCopyBuffer(commands, accumulation.buffer, hostBuffer.buffer, 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &toHost, 0, nullptr, 0, nullptr);
}

} // namespace

void recordCopyToHost(VkCommandBuffer commands, const Image& image, const Buffer& hostBuffer) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.width, image.height, 1};
    vkCmdCopyImageToBuffer(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           hostBuffer.buffer, 1, &region);
    // Make the copied bytes visible to the host's reads after the fence.
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &toHost, 0, nullptr, 0, nullptr);
}

Image8 imageFromHostCopy(const Image& image, const Buffer& hostBuffer) {
    Image8 pixels;
    pixels.width = static_cast<int>(image.width);
    pixels.height = static_cast<int>(image.height);
    pixels.rgba.resize(std::size_t(pixels.width) * pixels.height * 4);
    std::memcpy(pixels.rgba.data(), hostBuffer.mapped, pixels.rgba.size());
    return pixels;
}

void createHeadlessTarget(HeadlessTarget& target, const Context& context, const Renderer& renderer,
                          std::uint32_t fixedRegionSide) {
    OnFailure release([&] { destroyHeadlessTarget(target, context); });
    VkDeviceSize bytes = VkDeviceSize(renderer.outputImage.width) * renderer.outputImage.height * 4;
    target.readbackBuffer = createHostBuffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (renderer.settings.floatOutput)
        target.floatReadbackBuffer = createHostBuffer(
            context, VkDeviceSize(renderer.outputImage.width) * renderer.outputImage.height * 16,
            VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    // No watchdog guards a CPU device: it gets longer submissions (host/render/region_planner.h).
    const double targetMs = context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
                                ? kCpuTargetSubmissionMs
                                : kTargetSubmissionMs;
    target.planner = createRegionPlanner(fixedRegionSide, targetMs);

    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(context.device, &allocateInfo, &target.commands));

    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &target.submissionDone));
}

// One submission per region, each waited for before the next is recorded: the time of
// one sizes the next (host/render/region_planner.h), and the queue never holds more than one
// region's work, so nothing else waits behind a long frame.
FrameTiming renderHeadlessFrame(HeadlessTarget& target, const Context& context, Renderer& renderer,
                                ProgressMode progressMode) {
    const TraceRegion area = outputRegion(renderer.settings); // the crop, or all of the image
    Progress progress = startProgress(progressMode, area.width, area.height);
    const double totalPixels = double(area.width) * area.height;
    double pixelsDone = 0;
    FrameTiming timing;
    timing.gpuMs = renderer.timestampPool ? 0.0 : -1.0;

    // The planner tiles the area as if it were an image; its regions move to the area's place.
    beginFrame(target.planner, area.width, area.height);
    const Clock::time_point frameStart = Clock::now();
    TraceRegion region;
    bool begun = false; // the output image is in VK_IMAGE_LAYOUT_GENERAL
    while (nextRegion(target.planner, region)) {
        const bool last = frameCovered(target.planner);
        double milliseconds = 0.0;
        bool retrying = false;
        // A region whose invocations the driver cut short is traced again, in passes of
        // fewer samples, until none is or a pass is one sample.
        for (;;) {
            throwIfInterrupted(); // Ctrl-C: the last submission is done, nothing more is sent
            VK_CHECK(vkResetCommandBuffer(target.commands, 0));
            VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            VK_CHECK(vkBeginCommandBuffer(target.commands, &begin));
            if (!begun) recordTraceBegin(renderer, target.commands);
            // A last region traced again finds the image handed to the copy.
            if (retrying && last) recordTraceResume(renderer, target.commands);
            recordTraceRegion(renderer, target.commands,
                              {area.x + region.x, area.y + region.y, region.width, region.height});
            if (last) {
                recordTraceEnd(renderer, target.commands);
                // The last submission of a frame also copies the image to the readback buffer.
                recordCopyToHost(target.commands, renderer.outputImage, target.readbackBuffer);
                if (renderer.settings.floatOutput)
                    recordFloatCopyToHost(target.commands, renderer.accumulation,
                                          target.floatReadbackBuffer);
            }
            VK_CHECK(vkEndCommandBuffer(target.commands));
            resetKernelStatus(renderer);
            milliseconds += submitAndTime(target, context);
            begun = true;
            ++timing.submissions;
            const gpu::GpuKernelStatus status = kernelStatus(renderer);
            const std::uint32_t cutShort = status.cutShortInvocations;
            if (cutShort == 0) {
                timing.nodeVisits += status.nodeVisits;
                timing.leafPrimitiveTests += status.leafPrimitiveTests;
                break;
            }
            if (!traceFewerSamplesPerPass(renderer, context, renderer.settings.samplesPerPixel)) {
                timing.cutShortInvocations += cutShort;
                break;
            }
            retrying = true;
        }
        regionTraced(target.planner, region, milliseconds);
        timing.longestSubmissionMs = std::max(timing.longestSubmissionMs, milliseconds);
        if (renderer.timestampPool) timing.gpuMs += lastTraceGpuMilliseconds(renderer, context);
        pixelsDone += double(region.width) * region.height;
        updateProgress(progress, pixelsDone / totalPixels);
    }
    timing.wallMs = millisecondsSince(frameStart);
    if (timing.cutShortInvocations > 0)
        note("%s\n", cutShortWarning(timing.cutShortInvocations).c_str());
    finishProgress(progress, timing.submissions, timing.longestSubmissionMs);
    return timing;
}

Image8 readHeadlessImage(const HeadlessTarget& target, const Renderer& renderer) {
    return imageFromHostCopy(renderer.outputImage, target.readbackBuffer);
}

ImageF readHeadlessFloatImage(const HeadlessTarget& target, const Renderer& renderer) {
    if (!target.floatReadbackBuffer.buffer)
        throw std::logic_error("readHeadlessFloatImage: the renderer has no float output");
    ImageF image;
    image.width = static_cast<int>(renderer.outputImage.width);
    image.height = static_cast<int>(renderer.outputImage.height);
    image.rgb.resize(std::size_t(image.width) * image.height * 3);
    const auto* averages = static_cast<const float*>(target.floatReadbackBuffer.mapped);
    for (std::size_t pixel = 0; pixel < std::size_t(image.width) * image.height; ++pixel)
        for (std::size_t c = 0; c < 3; ++c)
            image.rgb[pixel * 3 + c] = averages[pixel * 4 + c];
    return image;
}

void destroyHeadlessTarget(HeadlessTarget& target, const Context& context) {
    if (context.device) vkDeviceWaitIdle(context.device);
    if (target.submissionDone) vkDestroyFence(context.device, target.submissionDone, nullptr);
    if (target.commands)
        vkFreeCommandBuffers(context.device, context.commandPool, 1, &target.commands);
    destroyBuffer(context, target.readbackBuffer);
    destroyBuffer(context, target.floatReadbackBuffer);
    target = HeadlessTarget{};
}
