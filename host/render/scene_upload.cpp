#include "render/scene_upload.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace {

struct ArrayView {
    std::uint32_t binding;
    const char* name;
    const void* data;
    VkDeviceSize bytes;
};

template <typename T>
ArrayView view(std::uint32_t binding, const char* name, const std::vector<T>& values) {
    return {binding, name, values.data(), values.size() * sizeof(T)};
}

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

} // namespace

GpuScene uploadScene(const Context& context, const PackedScene& packed) {
    // fp64: the double arrays take the place of the float ones (shaders/precision.glsl).
    const bool fp64 = !packed.spheres64.empty() || !packed.vertexPositions64.empty();
    const ArrayView arrays[] = {
        fp64 ? view(BINDING_SPHERES, "spheres", packed.spheres64)
             : view(BINDING_SPHERES, "spheres", packed.spheres),
        view(BINDING_SPHERE_MATERIALS, "sphere materials", packed.sphereMaterials),
        view(BINDING_TRIANGLES, "triangles", packed.triangleVertices),
        fp64 ? view(BINDING_VERTEX_POSITIONS, "vertex positions", packed.vertexPositions64)
             : view(BINDING_VERTEX_POSITIONS, "vertex positions", packed.vertexPositions),
        view(BINDING_VERTEX_NORMALS, "vertex normals", packed.vertexNormals),
        view(BINDING_MATERIALS, "materials", packed.materials),
        view(BINDING_LIGHTS, "lights", packed.lights),
        view(BINDING_BVH_NODES, "hierarchy nodes", packed.bvhNodes),
    };
    // A dvec4 array needs 32-byte alignment.
    const VkDeviceSize alignment = std::max<VkDeviceSize>(
        fp64 ? 32 : 16, context.properties.limits.minStorageBufferOffsetAlignment);
    const VkDeviceSize maxRange = context.properties.limits.maxStorageBufferRange;

    // Lay the arrays out one after another. An empty array still needs a valid
    // range to bind: all empty ones share one zeroed 16-byte slot at the start.
    GpuScene scene;
    VkDeviceSize size = alignment;
    VkDeviceSize offsets[BINDING_COUNT]{};
    for (const ArrayView& array : arrays) {
        if (array.bytes > maxRange)
            throw std::runtime_error(
                std::string("the scene's ") + array.name + " take " + std::to_string(array.bytes) +
                " bytes, more than this device's "
                "maxStorageBufferRange of " +
                std::to_string(maxRange) + " bytes (" + context.properties.deviceName + ")");
        offsets[array.binding] = array.bytes ? size : 0;
        size = alignUp(size + array.bytes, alignment);
    }
    std::vector<std::uint8_t> contents(size, 0);
    for (const ArrayView& array : arrays) {
        if (array.bytes)
            std::memcpy(contents.data() + offsets[array.binding], array.data, array.bytes);
    }
    scene.buffer =
        createDeviceBuffer(context, contents.data(), size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    for (const ArrayView& array : arrays)
        scene.ranges[array.binding] = {scene.buffer.buffer, offsets[array.binding],
                                       array.bytes ? array.bytes : 16};
    scene.bytes = size;
    scene.sphereCount = static_cast<std::uint32_t>(packed.spheres.size());
    scene.triangleCount = static_cast<std::uint32_t>(packed.triangleVertices.size() / 3);
    scene.lightCount = static_cast<std::uint32_t>(packed.lights.size());
    scene.bvhNodeCount = static_cast<std::uint32_t>(packed.bvhNodes.size());
    scene.ambient = packed.ambient;
    return scene;
}

void destroyGpuScene(const Context& context, GpuScene& scene) {
    destroyBuffer(context, scene.buffer);
    scene = GpuScene{};
}
