#include "scene_gpu.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

// The C++ mirror must have exactly the std430 layout the shader reads.
static_assert(sizeof(gpu::GpuMaterial) == 32);
static_assert(sizeof(gpu::GpuLight) == 32);
static_assert(sizeof(gpu::GpuFrameParams) == 96);
static_assert(sizeof(gpu::GpuFrameParams) <= 128, "push constants are limited to 128 bytes");
static_assert(offsetof(gpu::GpuFrameParams, image) == 48);
static_assert(offsetof(gpu::GpuFrameParams, tile) == 80);

namespace {

// Hashes the raw bytes of a trivially copyable key, so that exactly equal values
// (bit for bit) are merged and nothing else is.
template <typename T> struct BytesKey {
    T value;
    bool operator==(const BytesKey& other) const {
        return std::memcmp(&value, &other.value, sizeof(T)) == 0;
    }
};
template <typename T> struct BytesHash {
    std::size_t operator()(const BytesKey<T>& key) const {
        return std::hash<std::string_view>()(
            std::string_view(reinterpret_cast<const char*>(&key.value), sizeof(T)));
    }
};

// Gives each distinct value an index, in order of first appearance.
template <typename T> class Deduplicator {
  public:
    explicit Deduplicator(std::vector<T>& values) : values_(values) {}
    std::uint32_t indexOf(const T& value) {
        auto [it, inserted] = indices_.try_emplace(BytesKey<T>{value}, static_cast<std::uint32_t>(values_.size()));
        if (inserted) values_.push_back(value);
        return it->second;
    }

  private:
    std::vector<T>& values_;
    std::unordered_map<BytesKey<T>, std::uint32_t, BytesHash<T>> indices_;
};

glm::vec4 toVec4(const glm::dvec3& v, double w = 0.0) {
    return glm::vec4(glm::vec3(v), static_cast<float>(w));
}

gpu::GpuMaterial toGpuMaterial(const Material& material) {
    return {toVec4(material.diffuse, material.shininess), toVec4(material.specular)};
}

// A vertex as the GPU stores it, the unit of vertex deduplication.
struct PackedVertex {
    glm::vec4 position;
    glm::vec4 normal;
    std::uint32_t material;
};

} // namespace

PackedScene packScene(const Scene& scene) {
    PackedScene packed;
    packed.ambient = toVec4(scene.ambient);
    Deduplicator<gpu::GpuMaterial> materials(packed.materials);

    for (const Sphere& sphere : scene.spheres) {
        packed.spheres.push_back(toVec4(sphere.center, sphere.radius));
        packed.sphereMaterials.push_back(materials.indexOf(toGpuMaterial(sphere.material)));
    }

    std::vector<PackedVertex> vertices;
    Deduplicator<PackedVertex> vertexIndices(vertices);
    for (const Triangle& triangle : scene.triangles) {
        for (const Vertex& vertex : triangle.vertices) {
            PackedVertex packedVertex{};
            packedVertex.position = toVec4(vertex.position);
            packedVertex.normal = toVec4(vertex.normal);
            packedVertex.material = materials.indexOf(toGpuMaterial(vertex.material));
            packed.triangleVertices.push_back(vertexIndices.indexOf(packedVertex));
        }
    }
    for (const PackedVertex& vertex : vertices) {
        packed.vertexPositions.push_back(vertex.position);
        packed.vertexNormals.push_back(vertex.normal);
        packed.vertexMaterials.push_back(vertex.material);
    }

    for (const Light& light : scene.lights)
        packed.lights.push_back({toVec4(light.position), toVec4(light.color)});
    return packed;
}

namespace {

struct ArrayView {
    std::uint32_t binding;
    const char* name;
    const void* data;
    VkDeviceSize bytes;
};

template <typename T> ArrayView view(std::uint32_t binding, const char* name, const std::vector<T>& values) {
    return {binding, name, values.data(), values.size() * sizeof(T)};
}

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

} // namespace

GpuScene uploadScene(const Context& context, const PackedScene& packed) {
    const ArrayView arrays[] = {
        view(BINDING_SPHERES, "spheres", packed.spheres),
        view(BINDING_SPHERE_MATERIALS, "sphere materials", packed.sphereMaterials),
        view(BINDING_TRIANGLES, "triangles", packed.triangleVertices),
        view(BINDING_VERTEX_POSITIONS, "vertex positions", packed.vertexPositions),
        view(BINDING_VERTEX_NORMALS, "vertex normals", packed.vertexNormals),
        view(BINDING_VERTEX_MATERIALS, "vertex materials", packed.vertexMaterials),
        view(BINDING_MATERIALS, "materials", packed.materials),
        view(BINDING_LIGHTS, "lights", packed.lights),
    };
    const VkDeviceSize alignment =
        std::max<VkDeviceSize>(16, context.properties.limits.minStorageBufferOffsetAlignment);
    const VkDeviceSize maxRange = context.properties.limits.maxStorageBufferRange;

    // Lay the arrays out one after another. An empty array still needs a valid
    // range to bind: all empty ones share one zeroed 16-byte slot at the start.
    GpuScene scene;
    VkDeviceSize size = alignment;
    VkDeviceSize offsets[BINDING_COUNT]{};
    for (const ArrayView& array : arrays) {
        if (array.bytes > maxRange)
            throw std::runtime_error(std::string("the scene's ") + array.name + " take " +
                                     std::to_string(array.bytes) + " bytes, more than this device's "
                                     "maxStorageBufferRange of " + std::to_string(maxRange) + " bytes (" +
                                     context.properties.deviceName + ")");
        offsets[array.binding] = array.bytes ? size : 0;
        size = alignUp(size + array.bytes, alignment);
    }
    std::vector<std::uint8_t> contents(size, 0);
    for (const ArrayView& array : arrays) {
        if (array.bytes) std::memcpy(contents.data() + offsets[array.binding], array.data, array.bytes);
    }
    scene.buffer = createDeviceBuffer(context, contents.data(), size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    for (const ArrayView& array : arrays)
        scene.ranges[array.binding] = {scene.buffer.buffer, offsets[array.binding],
                                       array.bytes ? array.bytes : 16};
    scene.bytes = size;
    scene.sphereCount = static_cast<std::uint32_t>(packed.spheres.size());
    scene.triangleCount = static_cast<std::uint32_t>(packed.triangleVertices.size() / 3);
    scene.lightCount = static_cast<std::uint32_t>(packed.lights.size());
    scene.ambient = packed.ambient;
    return scene;
}

void destroyGpuScene(const Context& context, GpuScene& scene) {
    destroyBuffer(context, scene.buffer);
    scene = GpuScene{};
}
