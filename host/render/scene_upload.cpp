#include "render/scene_upload.h"

#include "base/parallel.h"
#include "base/release.h"
#include "base/scope_guard.h"
#include "gpu/vk_check.h"
#include "render/bindings.h"
#include "render/device_capacity.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>

namespace {

// One array of the scene buffer: its bytes, and how they are written at their place.
struct ArrayView {
    std::uint32_t binding;
    VkDeviceSize bytes;
    std::function<void(void* destination)> write;
};

// The bindings in the order their arrays are written: those whose sources go first first,
// the hierarchy's nodes (their own array), then the triangles' arrays (the triangles go
// after the third, the vertices after the fifth).
constexpr std::uint32_t kWriteOrder[] = {
    BINDING_BVH_NODES,
    BINDING_TRIANGLE_CORNERS,
    BINDING_TRIANGLE_LAST_VERTICES,
    BINDING_TRIANGLE_VERTICES,
    BINDING_VERTEX_POSITIONS,
    BINDING_VERTEX_NORMALS,
    BINDING_SPHERES,
    BINDING_SPHERE_MATERIALS,
    BINDING_MATERIALS,
    BINDING_LIGHTS,
    BINDING_VERTEX_TEXCOORDS,
    BINDING_MATERIAL_TEXTURES,
    BINDING_TEXTURE_PIXELS,
};

// packed's large arrays that no array still to be written is made of, released (an array
// of the other layout is empty, so written from the start).
void releaseWritten(const bool (&written)[BINDING_COUNT], PackedScene& packed) {
    if (written[BINDING_BVH_NODES]) release(packed.bvhNodes);
    if (written[BINDING_TRIANGLE_CORNERS] && written[BINDING_TRIANGLE_LAST_VERTICES] &&
        written[BINDING_TRIANGLE_VERTICES])
        release(packed.triangles);
    if (written[BINDING_TRIANGLE_CORNERS] && written[BINDING_VERTEX_POSITIONS] &&
        written[BINDING_VERTEX_NORMALS]) {
        release(packed.vertexNormals);
        release(packed.vertexPositions);
        release(packed.vertexPositions64);
    }
    if (written[BINDING_TEXTURE_PIXELS]) release(packed.texturePixels);
}

// An array copied as it is, in blocks on all threads: one thread's copy of a large scene's
// arrays (faulting in the mapped memory's pages as it went) was most of the upload.
template <typename T> ArrayView view(std::uint32_t binding, const std::vector<T>& values) {
    return {binding, values.size() * sizeof(T), [&values](void* destination) {
                const auto* from = reinterpret_cast<const std::uint8_t*>(values.data());
                auto* to = static_cast<std::uint8_t*>(destination);
                parallelForRanges(values.size() * sizeof(T), 1 << 20, [&](IndexRange range) {
                    std::memcpy(to + range.begin, from + range.begin, range.end - range.begin);
                });
            }};
}

// A triangle array written from the packed scene where it lands (scene_packing.h).
ArrayView written(std::uint32_t binding, std::size_t bytes,
                  void (*write)(const PackedScene&, void*), const PackedScene& packed) {
    return {binding, bytes, [write, &packed](void* destination) { write(packed, destination); }};
}

// An array of the layout not chosen: empty, bound to the zeroed slot.
ArrayView unused(std::uint32_t binding) {
    return {binding, 0, [](void*) {}};
}

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

// Both uploadScenes; released: packed, when its arrays go as they are written.
GpuScene upload(const Context& context, const PackedScene& packed, UploadLayout layout,
                PackedScene* released) {
    // fp64: the double arrays take the place of the float ones (shaders/precision.glsl).
    const bool fp64 = !packed.spheres64.empty() || !packed.vertexPositions64.empty();
    // The corners are derived from the packed arrays as they are written into the buffer's
    // memory: no host copy of them is made. Indexed triangles are the packed arrays as they are.
    const GpuTriangleArrayBytes triangleBytes = gpuTriangleArrayBytes(packed);
    const bool indexed = layout.indexedTriangles;
    const ArrayView arrays[] = {
        fp64 ? view(BINDING_SPHERES, packed.spheres64) : view(BINDING_SPHERES, packed.spheres),
        view(BINDING_SPHERE_MATERIALS, packed.sphereMaterials),
        indexed ? unused(BINDING_TRIANGLE_CORNERS)
                : written(BINDING_TRIANGLE_CORNERS, triangleBytes.corners, writeTriangleCorners,
                          packed),
        indexed ? unused(BINDING_TRIANGLE_LAST_VERTICES)
                : written(BINDING_TRIANGLE_LAST_VERTICES, triangleBytes.lastVertices,
                          writeLastVertices, packed),
        indexed ? view(BINDING_TRIANGLE_VERTICES, packed.triangles)
                : unused(BINDING_TRIANGLE_VERTICES),
        !indexed ? unused(BINDING_VERTEX_POSITIONS)
        : fp64   ? view(BINDING_VERTEX_POSITIONS, packed.vertexPositions64)
                 : view(BINDING_VERTEX_POSITIONS, packed.vertexPositions),
        written(BINDING_VERTEX_NORMALS, triangleBytes.normalsAndMaterials, writeNormalsAndMaterials,
                packed),
        view(BINDING_MATERIALS, packed.materials),
        view(BINDING_LIGHTS, packed.lights),
        view(BINDING_BVH_NODES, packed.bvhNodes),
        view(BINDING_VERTEX_TEXCOORDS, packed.vertexTexcoords),
        view(BINDING_MATERIAL_TEXTURES, packed.materialTextures),
        view(BINDING_TEXTURE_PIXELS, packed.texturePixels),
    };
    static_assert(std::size(kWriteOrder) == std::size(arrays));
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    const VkDeviceSize alignment = sceneArrayAlignment(limits, fp64);
    const VkDeviceSize maxRange = limits.maxStorageBufferRange;
    const VkDeviceSize maxBuffer =
        context.maxMemoryAllocationSize ? context.maxMemoryAllocationSize : ~VkDeviceSize(0);
    const std::string device = std::string(" (") + context.properties.deviceName + ")";
    VkDeviceSize bytesOf[BINDING_COUNT]{};
    for (const ArrayView& array : arrays)
        bytesOf[array.binding] = array.bytes;

    // Which arrays the kernel reads through their texel views: all it can (fp64's doubles
    // stay on the storage path), unless one exceeds maxTexelBufferElements.
    GpuScene scene;
    OnFailure release([&] { destroyGpuScene(context, scene); });
    auto viewed = [&](const BindingInfo& view) { return !(fp64 && view.doublesInFp64); };
    scene.texelReads = layout.texelReads;
    scene.indexedTriangles = indexed;
    for (const BindingInfo& view : kBindings) {
        if (view.role != BindingRole::SceneTexels) continue;
        const VkDeviceSize texels = bytesOf[view.source] / view.texelBytes;
        if (scene.texelReads && viewed(view) && texels > limits.maxTexelBufferElements) {
            scene.texelReads = false;
            scene.storageReadsNote = std::string("Storage-buffer reads: the scene's ") +
                                     kBindings[view.source].name + " take " +
                                     std::to_string(texels) +
                                     " texels, more than this device's maxTexelBufferElements "
                                     "of " +
                                     std::to_string(limits.maxTexelBufferElements);
        }
    }
    bool throughTexels[BINDING_COUNT]{};
    for (const BindingInfo& view : kBindings)
        if (view.role == BindingRole::SceneTexels && scene.texelReads && viewed(view))
            throughTexels[view.source] = true;
    // An array beyond maxStorageBufferRange is read through its texel view alone (which
    // reaches maxTexelBufferElements texels); its storage binding sees the zeroed slot.
    for (const ArrayView& array : arrays)
        if (array.bytes > maxRange && !throughTexels[array.binding])
            throw std::runtime_error(std::string("the scene's ") + kBindings[array.binding].name +
                                     " take " + std::to_string(array.bytes) +
                                     " bytes, more than this device's "
                                     "maxStorageBufferRange of " +
                                     std::to_string(maxRange) + " bytes" + device);

    // Lay the arrays out one after another, in a new buffer where the next would take this
    // one past maxMemoryAllocationSize. An empty array still needs a valid range to bind:
    // all empty ones share the zeroed 16-byte slot at the start of each buffer.
    struct Place {
        std::size_t buffer = 0;
        VkDeviceSize offset = 0; // 0: the zeroed slot (an empty array)
    };
    Place placed[BINDING_COUNT]{};
    std::vector<VkDeviceSize> sizes{alignment};
    for (const ArrayView& array : arrays) {
        if (!array.bytes) continue;
        if (alignUp(alignment + array.bytes, alignment) > maxBuffer)
            throw std::runtime_error(std::string("the scene's ") + kBindings[array.binding].name +
                                     " take " + std::to_string(array.bytes) +
                                     " bytes, more than this device's maxMemoryAllocationSize "
                                     "of " +
                                     std::to_string(maxBuffer) + " bytes" + device);
        if (alignUp(sizes.back() + array.bytes, alignment) > maxBuffer) sizes.push_back(alignment);
        placed[array.binding] = {sizes.size() - 1, sizes.back()};
        sizes.back() = alignUp(sizes.back() + array.bytes, alignment);
    }
    scene.sphereCount = static_cast<std::uint32_t>(packed.spheres.size());
    scene.triangleCount = static_cast<std::uint32_t>(packed.triangles.size());
    scene.lightCount = static_cast<std::uint32_t>(packed.lights.size());
    scene.ambient = packed.ambient;
    // Straight into each buffer's memory (or its staging copy): each array at its offset,
    // zeros in the shared slot and in each array's padding up to the next, so every byte is
    // written once (zeroing the whole buffer first wrote a large scene's twice).
    const ArrayView* arrayOf[BINDING_COUNT]{};
    bool written[BINDING_COUNT]{};
    for (const ArrayView& array : arrays) {
        arrayOf[array.binding] = &array;
        written[array.binding] = array.bytes == 0;
    }
    for (std::size_t k = 0; k < sizes.size(); ++k)
        scene.buffers.push_back(createFilledDeviceBuffer(
            context, sizes[k],
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
            [&](void* destination) {
                auto* bytes = static_cast<std::uint8_t*>(destination);
                std::memset(bytes, 0, alignment);
                for (const std::uint32_t binding : kWriteOrder) {
                    const ArrayView& array = *arrayOf[binding];
                    const Place& place = placed[binding];
                    if (!array.bytes || place.buffer != k) continue;
                    const VkDeviceSize end = place.offset + array.bytes;
                    array.write(bytes + place.offset);
                    std::memset(bytes + end, 0, alignUp(end, alignment) - end);
                    written[binding] = true;
                    if (released) releaseWritten(written, *released);
                }
            }));
    for (const ArrayView& array : arrays) {
        const Place& place = placed[array.binding];
        const bool bound = array.bytes && array.bytes <= maxRange;
        scene.ranges[array.binding] = {scene.buffers[place.buffer].buffer, bound ? place.offset : 0,
                                       bound ? array.bytes : 16};
    }

    // The views of arrays the kernel reads through storage bindings cover the zeroed slot.
    for (const BindingInfo& view : kBindings) {
        if (view.role != BindingRole::SceneTexels) continue;
        const Place& place = placed[view.source];
        const bool used = throughTexels[view.source] && bytesOf[view.source] > 0;
        VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
        info.buffer = scene.buffers[place.buffer].buffer;
        info.format = view.format;
        info.offset = used ? place.offset : 0;
        info.range = used ? bytesOf[view.source] : 16;
        VK_CHECK(
            vkCreateBufferView(context.device, &info, nullptr, &scene.texelViews[view.binding]));
    }
    scene.bytes = 0;
    for (const VkDeviceSize size : sizes)
        scene.bytes += size;
    for (const ArrayView& array : arrays)
        if (kBindings[array.binding].textureData) scene.textureBytes += array.bytes;
    return scene;
}

} // namespace

GpuScene uploadScene(const Context& context, const PackedScene& packed, UploadLayout layout) {
    return upload(context, packed, layout, nullptr);
}

GpuScene uploadScene(const Context& context, PackedScene&& packed, UploadLayout layout) {
    GpuScene scene = upload(context, packed, layout, &packed);
    packed = PackedScene{};
    return scene;
}

void updateGpuLights(const Context& context, GpuScene& scene,
                     const std::vector<gpu::GpuLight>& lights) {
    if (lights.size() != scene.lightCount)
        throw std::logic_error("updateGpuLights: " + std::to_string(lights.size()) +
                               " lights for a scene uploaded with " +
                               std::to_string(scene.lightCount));
    if (lights.empty()) return;
    VK_CHECK(vkDeviceWaitIdle(context.device)); // no trace in flight reads the old lights
    const VkDescriptorBufferInfo& range = scene.ranges[BINDING_LIGHTS];
    const VkDeviceSize bytes = lights.size() * sizeof(gpu::GpuLight);
    runOneTimeCommands(context, [&](VkCommandBuffer commands) {
        // A few lights: well under vkCmdUpdateBuffer's 65536 bytes, no staging buffer needed.
        vkCmdUpdateBuffer(commands, range.buffer, range.offset, bytes, lights.data());
        // The kernels of later submissions read them (storage or uniform texel buffer).
        VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        written.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        written.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &written, 0, nullptr, 0,
                             nullptr);
    });
}

void destroyGpuScene(const Context& context, GpuScene& scene) {
    for (VkBufferView view : scene.texelViews)
        if (view) vkDestroyBufferView(context.device, view, nullptr);
    for (Buffer& buffer : scene.buffers)
        destroyBuffer(context, buffer);
    scene = GpuScene{};
}
