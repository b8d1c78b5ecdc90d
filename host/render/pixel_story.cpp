#include "render/pixel_story.h"

#include "gpu/vk_check.h"

#include <cstring>
#include <stdexcept>

static_assert(sizeof(gpu::GpuStoryLight) == 32);
static_assert(sizeof(gpu::GpuStoryBounce) == 10 * 16 + MAX_STORY_LIGHTS * 32);
static_assert(sizeof(gpu::GpuPixelStory) == 5 * 16 + (MAX_DEPTH + 1) * sizeof(gpu::GpuStoryBounce));

gpu::GpuPixelStory tracePixelStory(Renderer& renderer, const Context& context, std::uint32_t x,
                                   std::uint32_t y, VkImageLayout outputLayout) {
    VK_CHECK(vkDeviceWaitIdle(context.device)); // the window's frames may still use the image
    if (!renderer.storyPipeline.pipeline) {
        TraceSpecialization specialization = renderer.specialization;
        specialization.recordPixel = VK_TRUE;
        renderer.storyPipeline = loadTracePipeline(
            context, {renderer.settings.shaderDirectory, renderer.settings.cacheDirectory},
            specialization, renderer.settings.kernel.precision);
    }
    // The kernel declares the output image in GENERAL; it does not write it, so its
    // contents (the last frame, which the window may blit again) are kept. Traced again in
    // passes of fewer samples while the driver cuts the invocation short (GpuKernelStatus).
    const Image& output = renderer.outputImage;
    for (;;) {
        std::memset(renderer.pixelStory.mapped, 0, sizeof(gpu::GpuPixelStory));
        resetKernelStatus(renderer);
        runOneTimeCommands(context, [&](VkCommandBuffer commands) {
            transitionImage(commands, output.image, outputLayout, VK_IMAGE_LAYOUT_GENERAL,
                            VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                            0);
            recordPixelStoryTrace(renderer, commands, x, y);
            transitionImage(commands, output.image, VK_IMAGE_LAYOUT_GENERAL,
                            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                            0);
            // Make the story's and the status's writes visible to the host after the wait.
            VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                 VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
        });
        if (cutShortInvocations(renderer) == 0 ||
            !traceFewerSamplesPerPass(renderer, context, renderer.settings.samplesPerPixel))
            break;
    }
    gpu::GpuPixelStory story;
    std::memcpy(&story, renderer.pixelStory.mapped, sizeof(story));
    if (story.counts.w != 1u)
        throw std::runtime_error("the kernel wrote no pixel story (a --shader-dir kernel without "
                                 "shaders/pixel_story.glsl's calls?)");
    return story;
}
