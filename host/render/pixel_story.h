// The pixel story (--pixel X,Y and the window's I key; docs/pixel_story.md): the ray tree
// of one pixel as the kernel traced it. A second kernel, compiled with SPEC_RECORD_PIXEL,
// traces that pixel alone and writes what it computes (shaders/pixel_story.glsl) into a
// GpuPixelStory (shaders/shared.h); the host reads it back and names each primitive by
// its index and line in the scene file. The normal kernel is untouched.
#pragma once

#include "render/renderer.h"
#include "shared.h"

#include <cstdint>
#include <string>

// Traces pixel (x, y) of the renderer's image with the recording kernel (compiled on
// first use and kept in the renderer) and returns what it wrote. The output image is not
// written; outputLayout is its layout now (UNDEFINED before any trace), and it is left in
// TRANSFER_SRC_OPTIMAL, as a frame leaves it. Waits for the device to be idle first.
gpu::GpuPixelStory tracePixelStory(Renderer& renderer, const Context& context, std::uint32_t x,
                                   std::uint32_t y, VkImageLayout outputLayout);

// What the story's JSON says about where it came from.
struct StoryHeader {
    std::string scene; // the scene file as given
    std::uint32_t x = 0, y = 0;
    std::uint32_t width = 0, height = 0, samples = 1, depth = 0;
};

// The story as one JSON object (docs/pixel_story.md), primitives named by their file
// index and line (renderer.sources).
std::string pixelStoryJson(const gpu::GpuPixelStory& story, const SlotSources& sources,
                           const StoryHeader& header);
