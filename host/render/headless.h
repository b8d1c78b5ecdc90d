// Headless frames: trace in several short submissions, copy the output image to host
// memory, wait. No window system.
#pragma once

#include "base/float_image.h"
#include "base/image_io.h"
#include "base/progress.h"
#include "render/region_planner.h"
#include "render/renderer.h"

struct HeadlessTarget {
    Buffer readbackBuffer; // host-visible copy of the output image, tightly packed RGBA8
    // With RenderSettings::floatOutput, host-visible copy of the float averages (vec4 per
    // pixel, row major) from the accumulation buffer.
    Buffer floatReadbackBuffer;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence submissionDone = VK_NULL_HANDLE;
    RegionPlanner planner; // what each submission traces; learns across frames
};

// What one frame cost.
struct FrameTiming {
    double wallMs = 0; // first submit to last fence, the host's work in between included
    double gpuMs = 0;  // sum of the timestamp intervals of the regions; < 0 without timestamps
    std::uint32_t submissions = 0;
    double longestSubmissionMs = 0; // submit to fence
    // Invocations the driver cut short even at one sample per pass: their pixels may be wrong
    // (a vector of invocations is cut short together).
    std::uint32_t cutShortInvocations = 0;
    // With RenderSettings::countWork: the hierarchy's work over the frame's last traces of
    // each region (GpuKernelStatus).
    std::uint64_t nodeVisits = 0, leafPrimitiveTests = 0;
};

// fixedRegionSide > 0 (--region-size) makes every region that square; 0 adapts the regions
// to about kTargetSubmissionMs each.
void createHeadlessTarget(HeadlessTarget& target, const Context& context, const Renderer& renderer,
                          std::uint32_t fixedRegionSide = 0);

// Traces one frame, region by region, and copies it to the readback buffer.
// Regions whose invocations the driver cut short are traced again with fewer samples per
// pass (traceFewerSamplesPerPass), which the renderer keeps for later frames; what is still
// cut short at one sample per pass is counted, and a warning says so.
FrameTiming renderHeadlessFrame(HeadlessTarget& target, const Context& context, Renderer& renderer,
                                ProgressMode progress = ProgressMode::Off);

// The last rendered frame as an image: the output image, which is the crop with one
// (RenderSettings::crop).
Image8 readHeadlessImage(const HeadlessTarget& target, const Renderer& renderer);

// The last rendered frame's averages before the 8-bit rounding (renderer made with
// RenderSettings::floatOutput): quantizeImage of them is readHeadlessImage, byte for byte.
ImageF readHeadlessFloatImage(const HeadlessTarget& target, const Renderer& renderer);

// Records the copy of image (in TRANSFER_SRC_OPTIMAL) into a host buffer of its size, and
// the barrier that makes it visible to the host once the submission's fence is signalled.
void recordCopyToHost(VkCommandBuffer commands, const Image& image, const Buffer& hostBuffer);

// The RGBA8 pixels of image as recordCopyToHost left them in hostBuffer.
Image8 imageFromHostCopy(const Image& image, const Buffer& hostBuffer);

void destroyHeadlessTarget(HeadlessTarget& target, const Context& context);
