// Records the trace kernel over the output image. Shared by the headless path and
// the window: both trace into the same RGBA8 UNORM image with the same kernel.
#pragma once

#include "gpu/context.h"
#include "gpu/resources.h"
#include "packing/triangle_layout.h"
#include "render/kernel_cache.h"
#include "render/region_planner.h"
#include "render/scene_upload.h"
#include "render/trace_pipeline.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

struct RenderSettings {
    std::uint32_t width = 640;
    std::uint32_t height = 480;
    std::uint32_t samplesPerPixel = 1;
    std::uint32_t depth = 5;
    glm::vec3 background{1.0f};
    double fovDegrees = 60.0;
    Acceleration acceleration = Acceleration::Auto;       // --accel: hierarchy or every primitive
    TriangleLayout triangleLayout = TriangleLayout::Auto; // --triangle-layout
    KernelChoices kernel;                 // --sampler, --seed, --precision and the method switches
    std::filesystem::path cacheDirectory; // shader and pipeline cache; empty: none (--no-cache)
    CameraPose camera;                    // the default camera unless --camera-* moved it
    std::filesystem::path
        shaderDirectory;      // --shader-dir: compile from here, uncached; empty: embedded
    bool progressive = false; // the window: keep a per-pixel running sum (BINDING_ACCUMULATION)
    // Headless -o out.pfm|out.exr: the kernel also writes each pixel's average, before the
    // 8-bit rounding, to the accumulation buffer (then a vec4 per pixel), for
    // readHeadlessFloatImage. The 8-bit image is written as always. Not with progressive.
    bool floatOutput = false;
    // --general-kernel (hidden): compile the kernel as if the scene held everything (spheres,
    // triangles, highlights, mirrors), keeping the method choices and the hierarchy, so that
    // tools/kernel_costs can measure what specialising for the scene's content gains. Same image.
    bool generalKernel = false;
    // --storage-reads (hidden): read the scene through the storage buffers, as for an array
    // beyond the device's maxTexelBufferElements, so that the tests reach that path. Same image.
    bool storageReads = false;
    // --count-work (hidden): the kernel counts the hierarchy's node visits and leaf
    // primitive tests (FrameTiming, --bench's JSON): a measure of work without timing noise.
    bool countWork = false;
    // --terminator: shadow rays leave smooth-shaded triangles from the hit point moved as
    // Hanika's shadow terminator fix does (shaders/shade.glsl); on for OBJ models by default.
    bool terminatorFix = false;
    // Headless --crop: the part of the width x height image that the output image holds and
    // the kernel traces, each pixel as in the full image; width 0: all of it. Only the part
    // must fit the device, so a poster larger than its image limit renders in such parts.
    TraceRegion crop{};
};

// The samples one dispatch adds (GpuFrameParams.dispatch.zw): count 0 traces all of
// samplesPerPixel in one pass; otherwise samples first..first+count-1 are added to the
// running sum (RenderSettings::progressive), first 0 starting it afresh.
// of: the sample count N the samples belong to (sampleOffset's n), when not the renderer's
// samplesPerPixel: the window's first frame is the one-sample image (of 1), the pixel centre.
struct SampleRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    std::uint32_t of = 0;
};

// Where each primitive slot of the kernel (leaf order) comes from in the scene file: its
// index among the file's spheres (triangles) and the line of its keyword; and each light's
// line. Kept on the host for the pixel story (host/render/pixel_story.h); never uploaded.
struct SlotSources {
    std::vector<std::uint32_t> sphereIndex, triangleIndex;
    std::vector<std::int64_t> sphereLine, triangleLine, lightLine;
};

struct Renderer {
    TracePipeline pipeline;
    bool pipelineShared = false; // pipeline belongs to a KernelCache (a batch), not to this
    GpuScene scene;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;
    // The kernel's output: written in VK_IMAGE_LAYOUT_GENERAL by the compute
    // shader, then read in TRANSFER_SRC_OPTIMAL by a copy (headless) or a blit (window).
    Image outputImage;
    // vec4 per pixel of outputImage: the running sum of the progressive view, in
    // VK_ACCESS_SHADER_READ/WRITE between dispatches, or the float averages
    // (settings.floatOutput); one vec4 when neither.
    Buffer accumulation;
    // The samples one dispatch traces at most; 0: all of them in one pass. Lowered by
    // traceFewerSamplesPerPass when the kernel reports invocations cut short.
    std::uint32_t samplesPerPass = 0;
    // BINDING_KERNEL_STATUS's host-visible GpuKernelStatus (resetKernelStatus before a
    // submission, cutShortInvocations after it).
    Buffer status;
    VkQueryPool timestampPool = VK_NULL_HANDLE; // two timestamps around the trace
    RenderSettings settings;
    TraceSpecialization specialization; // what the kernel was compiled for (--bench reports it)
    // The pixel story: BINDING_PIXEL_STORY's host-visible GpuPixelStory, and the recording
    // kernel that writes it, compiled on first use (host/render/pixel_story.h).
    Buffer pixelStory;
    TracePipeline storyPipeline;
    SlotSources sources;
};

// Packs and uploads the scene, compiles the kernel and creates the output image. The
// kernel is specialised for the settings and for what the scene holds
// (traceSpecialization). A shader that does not compile throws ShaderCompileError
// (host/gpu/shader_compiler.h); any failure releases what was made before it throws.
// With kernels (a batch), the pipeline comes from that cache and stays in it.
void createRenderer(Renderer& renderer, const Context& context, const Scene& scene,
                    const RenderSettings& settings, KernelCache* kernels = nullptr);

// createRenderer for a caller that needs no more of the scene's geometry: its triangles,
// meshes and textures are released as soon as packing has read them (a large model's mesh
// is then not held beside the packer's and the hierarchy's arrays and the GPU's copy: the
// start-up's peak of memory). Its lights, camera and the rest stay.
void createRendererReleasingGeometry(Renderer& renderer, const Context& context, Scene& scene,
                                     const RenderSettings& settings,
                                     KernelCache* kernels = nullptr);

// The specialization constants for this packed scene and these settings: its primitive
// kinds, hierarchy, whether any material has ks > 0, the method choices, and texel reads
// unless --storage-reads (createRenderer turns them off where the device's limit does). With
// settings.generalKernel the scene's content is ignored (everything on); the rest stays.
TraceSpecialization traceSpecialization(const PackedScene& packed, const RenderSettings& settings);

// The part of the full image the output image holds: settings.crop, or all of it.
TraceRegion outputRegion(const RenderSettings& settings);

// Recreates the output image at a new size (the window was resized), all of the image.
void resizeOutput(Renderer& renderer, const Context& context, std::uint32_t width,
                  std::uint32_t height);

// Records the whole frame's trace in one command buffer (the window): all samples, or
// with samples.count > 0 the next ones of the progressive sum, in passes of at most
// renderer.samplesPerPass samples. Afterwards the output
// image is ready to be read by a transfer command (copy or blit) in
// VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL.
void recordTrace(const Renderer& renderer, VkCommandBuffer commands, SampleRange samples = {});

// The kernel's report: zeroed before a submission, read once its fence has signalled.
void resetKernelStatus(const Renderer& renderer);
// Invocations whose loops the driver ended early since the reset: their pixels are wrong
// (GpuKernelStatus in shaders/shared.h).
std::uint32_t cutShortInvocations(const Renderer& renderer);
// The warning for invocations still cut short at one sample per dispatch.
std::string cutShortWarning(std::uint32_t invocations);
// The whole report, for the work counts of --count-work.
gpu::GpuKernelStatus kernelStatus(const Renderer& renderer);

// Halves the samples one dispatch traces (from all of them at first), so that an
// invocation runs fewer loop iterations; the image stays the same bits. Gives the per-pixel
// running sum room on the first split. False when a dispatch traces one sample already.
bool traceFewerSamplesPerPass(Renderer& renderer, const Context& context,
                              std::uint32_t samplesInFrame);

// Points the camera elsewhere (the window's controls); takes effect at the next record.
void setCamera(Renderer& renderer, const CameraPose& camera);

// Replaces the scene's lights with as many others (an OBJ model's rig placed for a new
// camera), rewriting only their part of the scene buffer; waits for the device to be idle.
void setLights(Renderer& renderer, const Context& context, const std::vector<Light>& lights);

// The vertical field of view of the next record (a frame of --camera-path).
void setFieldOfView(Renderer& renderer, double degrees);

// The same frame spread over several submissions (headless): recordTraceBegin in the
// first command buffer, recordTraceRegion for each region, recordTraceEnd in the last.
// The regions must cover the image; each pixel's value does not depend on them. A region
// traces its samples in passes of at most renderer.samplesPerPass.
void recordTraceBegin(const Renderer& renderer, VkCommandBuffer commands);
void recordTraceRegion(const Renderer& renderer, VkCommandBuffer commands,
                       const TraceRegion& region);
void recordTraceEnd(const Renderer& renderer, VkCommandBuffer commands);
// Undoes recordTraceEnd's hand-over, keeping the image, so that a region can be traced again
// after the frame's last submission (a region the driver cut short, traced in smaller passes).
void recordTraceResume(const Renderer& renderer, VkCommandBuffer commands);

// Records the recording kernel (renderer.storyPipeline, which must exist) for pixel (x, y)
// alone, its samples in passes of at most renderer.samplesPerPass; the output image must be
// in VK_IMAGE_LAYOUT_GENERAL.
void recordPixelStoryTrace(const Renderer& renderer, VkCommandBuffer commands, std::uint32_t x,
                           std::uint32_t y);

// The GPU time of the last finished recordTraceRegion from the timestamp queries, or a
// negative value when the device has no timestamps.
double lastTraceGpuMilliseconds(const Renderer& renderer, const Context& context);

void destroyRenderer(Renderer& renderer, const Context& context);
