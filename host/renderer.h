// Records the trace kernel over the output image. Shared by the headless path and
// the window: both trace into the same RGBA8 UNORM image with the same kernel.
#pragma once

#include "context.h"
#include "pipeline.h"
#include "resources.h"
#include "scene.h"
#include "scene_gpu.h"

#include <glm/glm.hpp>

#include <cstdint>

struct RenderSettings {
    std::uint32_t width = 640;
    std::uint32_t height = 480;
    std::uint32_t samplesPerPixel = 1;
    std::uint32_t depth = 5;
    glm::vec3 background{1.0f};
    double fovDegrees = 60.0;
};

struct Renderer {
    TracePipeline pipeline;
    GpuScene scene;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
    // The kernel's output: written in VK_IMAGE_LAYOUT_GENERAL by the compute
    // shader, then read in TRANSFER_SRC_OPTIMAL by a copy (headless) or a blit (window).
    Image outputImage;
    VkQueryPool timestampPool = VK_NULL_HANDLE; // two timestamps around the trace
    RenderSettings settings;
};

// Compiles the kernel, uploads the scene and creates the output image.
void createRenderer(Renderer& renderer, const Context& context, const Scene& scene,
                    const RenderSettings& settings);

// Recreates the output image at a new size (the window was resized).
void resizeOutput(Renderer& renderer, const Context& context, std::uint32_t width, std::uint32_t height);

// Records the whole frame's trace. Afterwards the output image is ready to be read
// by a transfer command (copy or blit) in VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL.
void recordTrace(const Renderer& renderer, VkCommandBuffer commands);

// The GPU time of the last finished trace from the timestamp queries, or a
// negative value when the device has no timestamps.
double lastTraceGpuMilliseconds(const Renderer& renderer, const Context& context);

void destroyRenderer(Renderer& renderer, const Context& context);
