#include "render/renderer.h"

#include "base/notes.h"
#include "base/parallel.h"
#include "base/populated_memory.h"
#include "base/recycled_pages.h"
#include "base/release.h"
#include "base/scope_guard.h"
#include "base/startup_phases.h"
#include "gpu/image_limits.h"
#include "gpu/vk_check.h"
#include "packing/workgroup_order.h"
#include "render/bindings.h"
#include "render/device_capacity.h"
#include "scene/scene_triangles.h"
#include "shared.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>

namespace {

// Each dispatch covers at most this many pixels a side. How much of the image one
// submission traces is the caller's choice (host/render/region_planner.h for headless frames).
constexpr std::uint32_t kMaxDispatchSide = 1024;

// A write of one descriptor of the kernel's set at binding (its type from the binding
// table); the caller points it at the buffer, view or image.
VkWriteDescriptorSet descriptorWrite(const Renderer& renderer, std::uint32_t binding) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = renderer.descriptorSet;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = bindingDescriptorType(binding);
    return write;
}

void createDescriptors(Renderer& renderer, const Context& context) {
    VkDescriptorPoolSize sizes[3];
    std::uint32_t kinds = 0;
    for (const VkDescriptorType type :
         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
          VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER})
        if (const std::uint32_t count = bindingsOfType(type)) sizes[kinds++] = {type, count};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = kinds;
    poolInfo.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(context.device, &poolInfo, nullptr, &renderer.descriptorPool));

    VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocateInfo.descriptorPool = renderer.descriptorPool;
    allocateInfo.descriptorSetCount = 1;
    allocateInfo.pSetLayouts = &renderer.pipeline.setLayout;
    VK_CHECK(vkAllocateDescriptorSets(context.device, &allocateInfo, &renderer.descriptorSet));

    // The scene's ranges never change; the output image and the running sum are written by
    // resizeOutput.
    std::vector<VkWriteDescriptorSet> writes;
    for (const BindingInfo& info : kBindings) {
        if (info.role != BindingRole::SceneArray && info.role != BindingRole::SceneTexels) continue;
        VkWriteDescriptorSet write = descriptorWrite(renderer, info.binding);
        if (info.role == BindingRole::SceneTexels)
            write.pTexelBufferView = &renderer.scene.texelViews[info.binding];
        else
            write.pBufferInfo = &renderer.scene.ranges[info.binding];
        writes.push_back(write);
    }
    // The story's buffer: only the recording kernel writes it, but every kernel declares it.
    const VkDescriptorBufferInfo storyInfo{renderer.pixelStory.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet storyWrite = descriptorWrite(renderer, BINDING_PIXEL_STORY);
    storyWrite.pBufferInfo = &storyInfo;
    writes.push_back(storyWrite);
    const VkDescriptorBufferInfo statusInfo{renderer.status.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet statusWrite = descriptorWrite(renderer, BINDING_KERNEL_STATUS);
    statusWrite.pBufferInfo = &statusInfo;
    writes.push_back(statusWrite);
    vkUpdateDescriptorSets(context.device, static_cast<std::uint32_t>(writes.size()), writes.data(),
                           0, nullptr);
}

// Each primitive's and light's line in the scene file, in file order: what the slots'
// sources need of the scene, taken before its geometry may be released.
struct FileLines {
    std::vector<std::int64_t> spheres, triangles, lights;
};

FileLines fileLines(const Scene& scene) {
    FileLines lines;
    for (const Sphere& sphere : scene.spheres)
        lines.spheres.push_back(sphere.line);
    lines.triangles = triangleLines(scene);
    for (const Light& light : scene.lights)
        lines.lights.push_back(light.line);
    return lines;
}

// Slot k's file index and line, from the packer's leaf order (its orders moved here).
SlotSources slotSources(FileLines lines, PackedScene& packed) {
    SlotSources sources;
    sources.sphereIndex = std::move(packed.sphereOrder);
    for (std::uint32_t index : sources.sphereIndex)
        sources.sphereLine.push_back(lines.spheres[index]);
    sources.triangleIndex = std::move(packed.triangleOrder);
    resizePopulated(sources.triangleLine, sources.triangleIndex.size());
    parallelForRanges(sources.triangleIndex.size(), 1 << 16, [&](IndexRange range) {
        for (std::size_t slot = range.begin; slot < range.end; ++slot)
            sources.triangleLine[slot] = lines.triangles[sources.triangleIndex[slot]];
    });
    sources.lightLine = std::move(lines.lights);
    return sources;
}

// What the renderer's packed copy replaces: the scene's triangles, meshes and textures.
void releaseGeometry(Scene& scene) {
    release(scene.triangles);
    release(scene.meshes);
    release(scene.textures);
}

// For a dispatch of workgroupRows rows of workgroups whose first pixel is (dispatchX, dispatchY).
gpu::GpuFrameParams frameParams(const Renderer& renderer, std::uint32_t dispatchX,
                                std::uint32_t dispatchY, std::uint32_t workgroupRows,
                                SampleRange samples) {
    const RenderSettings& settings = renderer.settings;
    const double tanHalfFov = std::tan(settings.fovDegrees * 0.5 * M_PI / 180.0);
    const double aspect = double(settings.width) / double(settings.height);
    gpu::GpuFrameParams params{};
    const TraceRegion output = outputRegion(settings);
    params.background =
        glm::vec4(settings.background, std::bit_cast<float>(output.x + output.width));
    params.ambient = glm::vec4(glm::vec3(renderer.scene.ambient),
                               std::bit_cast<float>(output.y + output.height));
    params.camera = glm::vec4(float(aspect * tanHalfFov), float(tanHalfFov),
                              std::bit_cast<float>(rowStride(workgroupRows)),
                              std::bit_cast<float>(std::uint32_t(LOOP_PROBE_ITERATIONS)));
    const glm::dquat orientation = cameraOrientation(settings.camera);
    params.cameraOrigin = glm::vec4(glm::vec3(settings.camera.position),
                                    std::bit_cast<float>(output.x | output.y << 16));
    params.cameraOrientation = glm::vec4(float(orientation.x), float(orientation.y),
                                         float(orientation.z), float(orientation.w));
    params.image = glm::uvec4(settings.width, settings.height,
                              samples.of != 0 ? samples.of : settings.samplesPerPixel,
                              std::min<std::uint32_t>(settings.depth, MAX_DEPTH));
    params.counts = glm::uvec4(renderer.scene.sphereCount, renderer.scene.triangleCount,
                               renderer.scene.lightCount, settings.kernel.seed);
    params.dispatch = glm::uvec4(dispatchX, dispatchY, samples.first, samples.count);
    return params;
}

} // namespace

TraceSpecialization traceSpecialization(const PackedScene& packed, const RenderSettings& settings) {
    TraceSpecialization specialization;
    specialization.useHierarchy = !packed.bvhNodes.empty();
    specialization.hasSpheres = !packed.spheres.empty();
    specialization.hasTriangles = !packed.triangles.empty();
    // Spheres and vertices only refer to materials in the list, so a ks > 0 that no
    // primitive uses is impossible; the check is on the float values the kernel reads.
    const auto& materials = packed.materials;
    auto hasKs = [](const gpu::GpuMaterial& m) {
        return m.specular.x > 0.0f || m.specular.y > 0.0f || m.specular.z > 0.0f;
    };
    auto mirrors = [&](const gpu::GpuMaterial& m) { return hasKs(m) && m.specular.w > 0.0f; };
    auto shares = [&](const gpu::GpuMaterial& m) { return hasKs(m) && m.specular.w != 1.0f; };
    specialization.hasSpecular = std::any_of(materials.begin(), materials.end(), hasKs);
    specialization.hasMirrors =
        settings.depth > 0 && std::any_of(materials.begin(), materials.end(), mirrors);
    specialization.hasMirrorShares =
        specialization.hasMirrors && std::any_of(materials.begin(), materials.end(), shares);
    specialization.shiftShadowOrigin = settings.terminatorFix && specialization.hasTriangles;
    specialization.hasTextures = !packed.materialTextures.empty() && specialization.hasTriangles;
    if (settings.generalKernel) {
        // Every content-dependent part stays in: the kernel any scene could run. The
        // spheres' and triangles' loops still stop at their counts (0 for an absent kind),
        // and the reflection loop at depth and ks = 0, so the image does not change.
        specialization.hasSpheres = specialization.hasTriangles = VK_TRUE;
        specialization.hasSpecular = specialization.hasMirrors = VK_TRUE;
        specialization.hasMirrorShares = VK_TRUE;
        specialization.hasTextures = VK_TRUE; // every material's texture width is 0 without
    }
    // A small scene's spheres baked in (shaders/baked_spheres.glsl): on the brute-force path
    // only, and not for the general kernel, whose point is to run any scene.
    if (!specialization.useHierarchy && !settings.generalKernel &&
        packed.spheres.size() <= MAX_BAKED_SPHERES) {
        specialization.bakedSpheres = VK_TRUE;
        specialization.bakedSphereCount = static_cast<std::uint32_t>(packed.spheres.size());
        specialization.bakedLightCount = static_cast<std::uint32_t>(packed.lights.size());
    }
    // The traversal stack holds one entry per level of the tree at most; a tree built by
    // packScene reports its depth (a lone leaf under the root needs one entry).
    if (specialization.useHierarchy && packed.hierarchy.used && !settings.generalKernel)
        specialization.stackDepth =
            std::clamp<std::uint32_t>(packed.hierarchy.depth, 1, BVH_STACK_SIZE);
    specialization.texelReads = !settings.storageReads;
    specialization.floatOutput = settings.floatOutput;
    specialization.outputPart = settings.crop.width > 0;
    specialization.countWork = settings.countWork;
    applyKernelChoices(specialization, settings.kernel);
    return specialization;
}

namespace {

// A running sum per pixel is needed when the samples are added over several dispatches:
// the window's progressive view, or a headless frame split into passes; float output keeps
// its averages there too.
bool needsPerPixelSum(const Renderer& renderer) {
    const RenderSettings& settings = renderer.settings;
    return settings.progressive || settings.floatOutput ||
           (renderer.samplesPerPass != 0 && renderer.samplesPerPass < settings.samplesPerPixel);
}

// The accumulation buffer at the output image's size (a vec4 per pixel when the renderer
// needs a running sum, else one), bound to the kernel.
void createAccumulation(Renderer& renderer, const Context& context) {
    // Its contents never matter: the first dispatch of a progressive run or of a split frame
    // writes before it reads, float output writes every pixel, and other one-pass dispatches
    // never touch it.
    destroyBuffer(context, renderer.accumulation);
    const bool perPixel = needsPerPixelSum(renderer);
    const VkDeviceSize accumulationBytes = perPixel
                                               ? VkDeviceSize(renderer.outputImage.width) *
                                                     renderer.outputImage.height * sizeof(glm::vec4)
                                               : sizeof(glm::vec4);
    const VkDeviceSize storageRange = context.properties.limits.maxStorageBufferRange;
    if (perPixel && accumulationBytes > storageRange)
        throw std::runtime_error(
            "a " + std::to_string(renderer.outputImage.width) + "x" +
            std::to_string(renderer.outputImage.height) +
            (renderer.settings.floatOutput ? " float image" : " image traced in sample passes") +
            " needs " + std::to_string(accumulationBytes >> 20) + " MiB, more than this device's " +
            "maxStorageBufferRange of " + std::to_string(storageRange >> 20) + " MiB (" +
            context.properties.deviceName + "); " +
            (renderer.settings.floatOutput ? "write a PNG or a smaller image"
                                           : "render a smaller image, or in --crop regions"));
    const std::vector<std::uint8_t> zeros(accumulationBytes, 0);
    // TRANSFER_SRC: headless float output copies it to a host buffer.
    renderer.accumulation =
        createDeviceBuffer(context, zeros.data(), accumulationBytes,
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    VkDescriptorBufferInfo bufferInfo{renderer.accumulation.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet bufferWrite = descriptorWrite(renderer, BINDING_ACCUMULATION);
    bufferWrite.pBufferInfo = &bufferInfo;
    vkUpdateDescriptorSets(context.device, 1, &bufferWrite, 0, nullptr);
}

// The output image, width x height, bound to the kernel, and its accumulation buffer.
void createOutput(Renderer& renderer, const Context& context, std::uint32_t width,
                  std::uint32_t height) {
    VK_CHECK(vkDeviceWaitIdle(context.device));
    destroyImage(context, renderer.outputImage);
    renderer.outputImage =
        createImage(context, width, height, VK_FORMAT_R8G8B8A8_UNORM,
                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);

    VkDescriptorImageInfo imageInfo{VK_NULL_HANDLE, renderer.outputImage.view,
                                    VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet imageWrite = descriptorWrite(renderer, BINDING_OUTPUT_IMAGE);
    imageWrite.pImageInfo = &imageInfo;
    vkUpdateDescriptorSets(context.device, 1, &imageWrite, 0, nullptr);

    createAccumulation(renderer, context);
}
// createRenderer, with onPacked() called once packing has read all it needs of the scene
// (readForPacking): where createRendererReleasingGeometry lets the scene's geometry go.
void createRendererFrom(Renderer& renderer, const Context& context, const Scene& scene,
                        const RenderSettings& settings, KernelCache* kernels,
                        const std::function<void()>& onPacked) {
    OnFailure release([&] { destroyRenderer(renderer, context); });
    renderer.settings = settings;
    if (settings.floatOutput && settings.progressive)
        throw std::logic_error("float output is for one-pass (headless) frames only");
    const Precision precision = settings.kernel.precision;
    if (precision == Precision::Fp64 && !context.float64Enabled)
        throw std::logic_error("--precision fp64, but the device was created without shaderFloat64 "
                               "(createDevice needFloat64)");
    FileLines lines = fileLines(scene);
    PackedScene packed;
    {
        const PhaseTimer timer("pack");
        PackingInputPtr input = readForPacking(scene, precision);
        onPacked(); // the scene's geometry may go: packing needs no more of it
        packed = finishPacking(std::move(input));
    }
    arrangeForHierarchy(packed, settings.acceleration);
    note("%s\n", accelerationSummary(packed.hierarchy).c_str());
    renderer.sources = slotSources(std::move(lines), packed);
    renderer.specialization = traceSpecialization(packed, settings);
    {
        SceneCapacity corners =
            sceneCapacityOf(context, !settings.storageReads, precision == Precision::Fp64);
        allowTriangleLayouts(corners, TriangleLayout::Corners);
        const LayoutRoom room{packed.triangles.size() <= triangleCapacity(corners).triangles,
                              imageLimitsOf(context).largestDeviceLocalHeap};
        renderer.specialization.indexedTriangles =
            !packed.triangles.empty() && indexedTriangles(packed, settings.triangleLayout, room);
    }
    const KernelSource source{settings.shaderDirectory, settings.cacheDirectory};
    auto loadKernel = [&] {
        const PhaseTimer kernelTimer("kernel");
        if (kernels) {
            renderer.pipeline =
                cachedTracePipeline(*kernels, context, source, renderer.specialization, precision);
            renderer.pipelineShared = true;
        } else {
            renderer.pipeline =
                loadTracePipeline(context, source, renderer.specialization, precision);
        }
    };
    // The driver's memory for the scene does not come from the recycled pages: freed pages
    // kept from here on would only add to it.
    const PagesGivenBack givenBack;
    // The kernel compiles on a second thread while the scene uploads (the two phases' times
    // overlap), for the texel reads asked for; one after the other with --threads 1.
    parallelFor(2, [&](std::size_t part) {
        if (part == 1) return loadKernel();
        const PhaseTimer timer("upload");
        // packed's arrays go as they are written: the GPU holds them now.
        renderer.scene = uploadScene(context, std::move(packed),
                                     {renderer.specialization.texelReads != VK_FALSE,
                                      renderer.specialization.indexedTriangles != VK_FALSE});
    });
    // The upload turns texel reads off for an array beyond maxTexelBufferElements: the
    // kernel is then compiled again, for storage-buffer reads.
    if (renderer.scene.texelReads != (renderer.specialization.texelReads != VK_FALSE)) {
        if (!renderer.pipelineShared) destroyTracePipeline(context, renderer.pipeline);
        renderer.specialization.texelReads = renderer.scene.texelReads;
        loadKernel();
    }
    if (!renderer.scene.storageReadsNote.empty())
        note("%s\n", renderer.scene.storageReadsNote.c_str());
    const std::size_t primitives = renderer.scene.sphereCount + renderer.scene.triangleCount;
    if (primitives > 0 && renderer.scene.textureBytes > 0)
        note("Scene memory: %llu bytes, %.1f bytes per primitive; textures %llu of them\n",
             static_cast<unsigned long long>(renderer.scene.bytes),
             double(renderer.scene.bytes) / double(primitives),
             static_cast<unsigned long long>(renderer.scene.textureBytes));
    else if (primitives > 0)
        note("Scene memory: %llu bytes, %.1f bytes per primitive\n",
             static_cast<unsigned long long>(renderer.scene.bytes),
             double(renderer.scene.bytes) / double(primitives));
    renderer.pixelStory =
        createHostBuffer(context, sizeof(gpu::GpuPixelStory), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    renderer.status =
        createHostBuffer(context, sizeof(gpu::GpuKernelStatus), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    resetKernelStatus(renderer);
    createDescriptors(renderer, context);
    if (context.timestampsSupported) {
        VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
        queryInfo.queryCount = 2;
        VK_CHECK(vkCreateQueryPool(context.device, &queryInfo, nullptr, &renderer.timestampPool));
    }
    const TraceRegion output = outputRegion(settings);
    if (output.x >= MAX_IMAGE_SIDE || output.y >= MAX_IMAGE_SIDE)
        throw std::invalid_argument("a region's origin must lie within " +
                                    std::to_string(MAX_IMAGE_SIDE) + " pixels (GpuFrameParams)");
    createOutput(renderer, context, output.width, output.height);
}

} // namespace

void createRenderer(Renderer& renderer, const Context& context, const Scene& scene,
                    const RenderSettings& settings, KernelCache* kernels) {
    createRendererFrom(renderer, context, scene, settings, kernels, [] {});
}

void createRendererReleasingGeometry(Renderer& renderer, const Context& context, Scene& scene,
                                     const RenderSettings& settings, KernelCache* kernels) {
    createRendererFrom(renderer, context, scene, settings, kernels,
                       [&] { releaseGeometry(scene); });
}

TraceRegion outputRegion(const RenderSettings& settings) {
    if (settings.crop.width > 0) return settings.crop;
    return {0, 0, settings.width, settings.height};
}

void resizeOutput(Renderer& renderer, const Context& context, std::uint32_t width,
                  std::uint32_t height) {
    renderer.settings.width = width;
    renderer.settings.height = height;
    renderer.settings.crop = {};
    createOutput(renderer, context, width, height);
}

void setCamera(Renderer& renderer, const CameraPose& camera) {
    renderer.settings.camera = camera;
}

void setLights(Renderer& renderer, const Context& context, const std::vector<Light>& lights) {
    updateGpuLights(context, renderer.scene, packLights(lights));
}

void setFieldOfView(Renderer& renderer, double degrees) {
    renderer.settings.fovDegrees = degrees;
}

void recordTraceBegin(const Renderer& renderer, VkCommandBuffer commands) {
    // Wait for the previous frame's copy or blit to finish reading before writing.
    // Every pixel is rewritten, so the old contents are discarded (UNDEFINED). The
    // barrier also orders the writes of later submissions of this frame: its scope is
    // everything after it in submission order.
    transitionImage(commands, renderer.outputImage.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
}

namespace {

// The dispatches of one pass over the region: samples (count 0: all, in one pass).
void recordPass(const Renderer& renderer, VkCommandBuffer commands, const TraceRegion& region,
                SampleRange samples) {
    // Regions write disjoint pixels, so the dispatches need no barrier between them.
    const std::uint32_t right = region.x + region.width, bottom = region.y + region.height;
    for (std::uint32_t dispatchY = region.y; dispatchY < bottom; dispatchY += kMaxDispatchSide) {
        for (std::uint32_t dispatchX = region.x; dispatchX < right; dispatchX += kMaxDispatchSide) {
            const std::uint32_t dispatchWidth = std::min(kMaxDispatchSide, right - dispatchX);
            const std::uint32_t dispatchHeight = std::min(kMaxDispatchSide, bottom - dispatchY);
            const std::uint32_t columns = (dispatchWidth + WORKGROUP_SIZE_X - 1) / WORKGROUP_SIZE_X;
            const std::uint32_t rows = (dispatchHeight + WORKGROUP_SIZE_Y - 1) / WORKGROUP_SIZE_Y;
            gpu::GpuFrameParams params = frameParams(renderer, dispatchX, dispatchY, rows, samples);
            vkCmdPushConstants(commands, renderer.pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                               sizeof(params), &params);
            vkCmdDispatch(commands, columns, rows, 1);
        }
    }
}

// The running sum written by one pass is read and written by the next.
void recordSumBarrier(VkCommandBuffer commands) {
    VkMemoryBarrier sum{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    sum.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    sum.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &sum, 0, nullptr, 0, nullptr);
}

// Calls recordOne for each pass of samples (count 0: all of the frame's) of at most
// renderer.samplesPerPass samples, with the barrier between passes that the running sum
// needs; all of the frame's samples fit in one pass as count 0.
template <typename RecordOne>
void forEachPass(const Renderer& renderer, VkCommandBuffer commands, SampleRange samples,
                 RecordOne recordOne) {
    const std::uint32_t perPass = renderer.samplesPerPass;
    const std::uint32_t all = std::max(renderer.settings.samplesPerPixel, 1u);
    if (samples.count == 0 && (perPass == 0 || perPass >= all)) {
        recordOne(SampleRange{});
        return;
    }
    if (samples.count == 0) samples = {0, all};
    const std::uint32_t end = samples.first + samples.count;
    for (std::uint32_t first = samples.first; first < end;) {
        const std::uint32_t count = perPass == 0 ? end - first : std::min(perPass, end - first);
        if (first != samples.first) recordSumBarrier(commands);
        recordOne(SampleRange{first, count, samples.of});
        first += count;
    }
}

// Samples (count 0: all of the frame's) over the region, in passes (forEachPass).
void recordRegion(const Renderer& renderer, VkCommandBuffer commands, const TraceRegion& region,
                  SampleRange samples) {
    if (renderer.timestampPool) {
        vkCmdResetQueryPool(commands, renderer.timestampPool, 0, 2);
        vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, renderer.timestampPool, 0);
    }
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, renderer.pipeline.pipeline);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, renderer.pipeline.layout, 0,
                            1, &renderer.descriptorSet, 0, nullptr);
    forEachPass(renderer, commands, samples,
                [&](SampleRange pass) { recordPass(renderer, commands, region, pass); });
    if (renderer.timestampPool)
        vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, renderer.timestampPool,
                            1);
    // The kernel's report (GpuKernelStatus), to the host's read after the fence.
    VkMemoryBarrier report{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    report.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    report.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &report, 0, nullptr, 0, nullptr);
}

} // namespace

void recordTraceRegion(const Renderer& renderer, VkCommandBuffer commands,
                       const TraceRegion& region) {
    recordRegion(renderer, commands, region, {});
}

void recordTraceEnd(const Renderer& renderer, VkCommandBuffer commands) {
    // Make the kernel's writes, from this and earlier submissions, visible to the copy
    // or blit that follows.
    transitionImage(commands, renderer.outputImage.image, VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                    VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
}

void recordTraceResume(const Renderer& renderer, VkCommandBuffer commands) {
    transitionImage(commands, renderer.outputImage.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void recordTrace(const Renderer& renderer, VkCommandBuffer commands, SampleRange samples) {
    recordTraceBegin(renderer, commands);
    // The running sum written by the previous frame's dispatches is read by this one's.
    if (samples.count > 0) recordSumBarrier(commands);
    recordRegion(renderer, commands,
                 {0, 0, renderer.outputImage.width, renderer.outputImage.height}, samples);
    recordTraceEnd(renderer, commands);
}

void resetKernelStatus(const Renderer& renderer) {
    std::memset(renderer.status.mapped, 0, sizeof(gpu::GpuKernelStatus));
}

gpu::GpuKernelStatus kernelStatus(const Renderer& renderer) {
    gpu::GpuKernelStatus status;
    std::memcpy(&status, renderer.status.mapped, sizeof(status));
    return status;
}

std::string cutShortWarning(std::uint32_t invocations) {
    return "warning: " + std::to_string(invocations) +
           " pixels may be wrong: the CPU driver ends a shader invocation's loops after 65535 "
           "iterations in all, and one sample of these pixels needs more (more bounces, lights "
           "or primitives tested than it allows; --accel bvh tests fewer)";
}

std::uint32_t cutShortInvocations(const Renderer& renderer) {
    return kernelStatus(renderer).cutShortInvocations;
}

bool traceFewerSamplesPerPass(Renderer& renderer, const Context& context,
                              std::uint32_t samplesInFrame) {
    const std::uint32_t now = renderer.samplesPerPass == 0
                                  ? std::max(renderer.settings.samplesPerPixel, samplesInFrame)
                                  : renderer.samplesPerPass;
    if (now <= 1) return false;
    const bool hadSum = needsPerPixelSum(renderer);
    renderer.samplesPerPass = std::min(now, samplesInFrame) / 2;
    renderer.samplesPerPass = std::max(renderer.samplesPerPass, 1u);
    if (!hadSum && needsPerPixelSum(renderer)) {
        VK_CHECK(vkDeviceWaitIdle(context.device));
        createAccumulation(renderer, context);
    }
    return true;
}

void recordPixelStoryTrace(const Renderer& renderer, VkCommandBuffer commands, std::uint32_t x,
                           std::uint32_t y) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, renderer.storyPipeline.pipeline);
    // The story pipeline's set layout is defined exactly as the trace pipeline's, so the
    // renderer's descriptor set is compatible with it.
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, renderer.storyPipeline.layout,
                            0, 1, &renderer.descriptorSet, 0, nullptr);
    // The pixel first in the dispatch: the invocation (0, 0) of workgroup (0, 0) traces it,
    // in passes of at most renderer.samplesPerPass samples (its running sum in the story).
    forEachPass(renderer, commands, {}, [&](SampleRange pass) {
        const gpu::GpuFrameParams params = frameParams(renderer, x, y, 1, pass);
        vkCmdPushConstants(commands, renderer.storyPipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           sizeof(params), &params);
        vkCmdDispatch(commands, 1, 1, 1);
    });
}

double lastTraceGpuMilliseconds(const Renderer& renderer, const Context& context) {
    if (!renderer.timestampPool) return -1.0;
    std::uint64_t ticks[2] = {};
    VK_CHECK(vkGetQueryPoolResults(context.device, renderer.timestampPool, 0, 2, sizeof(ticks),
                                   ticks, sizeof(std::uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    return double(ticks[1] - ticks[0]) * context.properties.limits.timestampPeriod * 1e-6;
}

void destroyRenderer(Renderer& renderer, const Context& context) {
    if (context.device) vkDeviceWaitIdle(context.device);
    destroyImage(context, renderer.outputImage);
    destroyBuffer(context, renderer.accumulation);
    destroyBuffer(context, renderer.pixelStory);
    destroyBuffer(context, renderer.status);
    destroyTracePipeline(context, renderer.storyPipeline);
    if (renderer.timestampPool) vkDestroyQueryPool(context.device, renderer.timestampPool, nullptr);
    if (renderer.descriptorPool)
        vkDestroyDescriptorPool(context.device, renderer.descriptorPool, nullptr);
    destroyGpuScene(context, renderer.scene);
    if (!renderer.pipelineShared) destroyTracePipeline(context, renderer.pipeline);
    renderer = Renderer{};
}
