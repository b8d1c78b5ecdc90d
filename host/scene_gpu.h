// Packs a parsed scene into the GPU layout of shaders/shared.h and uploads it.
// Only what the scene holds is packed: identical materials and identical vertices
// are stored once, and a sphere pays for no triangle fields.
#pragma once

#include "resources.h"
#include "scene.h"
#include "shared.h"

#include <cstdint>
#include <vector>

// The scene as the GPU sees it, still on the CPU (easy to test).
struct PackedScene {
    std::vector<glm::vec4> spheres;               // centre xyz, radius w
    std::vector<std::uint32_t> sphereMaterials;   // index into materials
    std::vector<std::uint32_t> triangleVertices;  // 3 vertex indices per triangle
    std::vector<glm::vec4> vertexPositions;       // xyz, w = 0
    std::vector<glm::vec4> vertexNormals;         // xyz as given, w = 0
    std::vector<std::uint32_t> vertexMaterials;   // index into materials
    std::vector<gpu::GpuMaterial> materials;      // each distinct material once
    std::vector<gpu::GpuLight> lights;
    glm::vec4 ambient{0.0f};
};

PackedScene packScene(const Scene& scene);

// All scene arrays live in one device buffer; each binding sees its own range.
struct GpuScene {
    Buffer buffer;
    VkDescriptorBufferInfo ranges[BINDING_COUNT]{}; // BINDING_OUTPUT_IMAGE's entry unused
    VkDeviceSize bytes = 0;                         // device memory holding the scene
    std::uint32_t sphereCount = 0;
    std::uint32_t triangleCount = 0;
    std::uint32_t lightCount = 0;
    glm::vec4 ambient{0.0f};
};

// Throws with the limit's name when an array exceeds maxStorageBufferRange.
GpuScene uploadScene(const Context& context, const PackedScene& packed);

void destroyGpuScene(const Context& context, GpuScene& scene);
