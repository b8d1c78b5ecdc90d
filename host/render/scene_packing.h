// Packs a parsed scene into the GPU layout of shaders/shared.h and uploads it.
// Only what the scene holds is packed: identical materials and identical vertices
// are stored once, and a sphere pays for no triangle fields.
#pragma once

#include "gpu/resources.h"
#include "render/bvh.h"
#include "render/kernel_choices.h"
#include "scene/scene_loader.h"
#include "shared.h"

#include <cstdint>
#include <vector>

// The scene as the GPU sees it, still on the CPU (easy to test).
struct PackedScene {
    std::vector<glm::vec4> spheres;              // centre xyz, radius w
    std::vector<std::uint32_t> sphereMaterials;  // index into materials
    std::vector<std::uint32_t> triangleVertices; // 3 vertex indices per triangle
    std::vector<glm::vec4> vertexPositions;      // xyz; w: index into materials (uint bits)
    std::vector<float> vertexNormals;            // 3 per vertex: xyz as given
    std::vector<gpu::GpuMaterial> materials;     // each distinct material once
    std::vector<gpu::GpuLight> lights;
    std::vector<gpu::GpuBvhNode> bvhNodes; // empty: the shader tests every primitive
    glm::vec4 ambient{0.0f};
    // --precision fp64 only (else empty): the same spheres and vertex positions in double,
    // which the GPU then gets instead of the float ones; a position's w is its material
    // index as a double. Vertices are shared only when their doubles are equal.
    std::vector<glm::dvec4> spheres64;
    std::vector<glm::dvec4> vertexPositions64;
};

// Spheres and triangles in file order, materials and vertices shared; no hierarchy.
PackedScene packScene(const Scene& scene, Precision precision = Precision::Fp32);

// The material index of vertex v, from its position's w.
std::uint32_t vertexMaterial(const PackedScene& packed, std::size_t v);

// The box of every sphere, then of every triangle, slightly enlarged (see scene_gpu.cpp);
// from the doubles when the scene was packed for fp64, rounded outward to float.
PrimitiveBounds primitiveBounds(const PackedScene& packed);

// Stores the spheres (with their materials) and triangles in the hierarchy's leaf order,
// so that each leaf's primitives are consecutive. Vertices and materials are untouched.
// Reordering the arrays themselves, rather than adding an array of primitive references
// that the leaves index, costs no memory (a reference would add 4 bytes a primitive) and
// no dependent load before each primitive test. The price: a leaf holds one kind (the
// builder splits a mixed range in two), and the shader's primitive indices are leaf-order
// slots, not file order; both paths use the slots and the same tie rule, so --accel bvh
// and --accel none still give identical images.
void applyLeafOrder(PackedScene& packed, const Bvh& bvh);

// All scene arrays live in one device buffer; each binding sees its own range.
struct GpuScene {
    Buffer buffer;
    VkDescriptorBufferInfo ranges[BINDING_COUNT]{}; // BINDING_OUTPUT_IMAGE's entry unused
    VkDeviceSize bytes = 0;                         // device memory holding the scene
    std::uint32_t sphereCount = 0;
    std::uint32_t triangleCount = 0;
    std::uint32_t lightCount = 0;
    std::uint32_t bvhNodeCount = 0; // 0: no hierarchy
    glm::vec4 ambient{0.0f};
};

// Throws with the limit's name when an array exceeds maxStorageBufferRange.
GpuScene uploadScene(const Context& context, const PackedScene& packed);

void destroyGpuScene(const Context& context, GpuScene& scene);
