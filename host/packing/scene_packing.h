// Packs a parsed scene into the GPU layout of shaders/shared.h (render/scene_upload.h
// then uploads it).
// Only what the scene holds is packed: identical materials and identical vertices
// are stored once, and a sphere pays for no triangle fields.
#pragma once

#include "packing/bvh.h"
#include "packing/kernel_choices.h"
#include "scene/scene.h"
#include "shared.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

// How the hierarchy came out: what the renderer reports on stderr.
struct HierarchyReport {
    bool used = false;          // false: the shader tests every primitive
    std::size_t primitives = 0; // spheres + triangles
    std::size_t nodes = 0;      // built (used or not)
    std::uint32_t depth = 0;
    double buildMs = 0;
};

// "Acceleration: BVH, N two-wide nodes, depth D, built in T ms" or
// "Acceleration: none, every primitive tested (N primitives)".
std::string accelerationSummary(const HierarchyReport& report);

// The scene as the GPU sees it, still on the CPU (easy to test); the triangles and vertices
// are rearranged for the kernel at upload (gpuTriangleArrays).
struct PackedScene {
    std::vector<glm::vec4> spheres;             // centre xyz, radius w
    std::vector<std::uint32_t> sphereMaterials; // index into materials
    // Per triangle, its vertex indices in xyz and its flat patch in w (flat_patches.h).
    std::vector<glm::uvec4> triangles;
    std::vector<glm::vec4> vertexPositions;  // xyz; w: index into materials (uint bits)
    std::vector<float> vertexNormals;        // 3 per vertex: xyz as given
    std::vector<gpu::GpuMaterial> materials; // each distinct material once
    std::vector<gpu::GpuLight> lights;
    std::vector<gpu::GpuBvhNode> bvhNodes; // empty: the shader tests every primitive
    // Only when the scene has textures (else all three empty): per vertex its texture
    // coordinates, per material where its texture lies (width 0: none), and every texture's
    // texels, RGBA8 in a uint each, texture after texture.
    std::vector<glm::vec2> vertexTexcoords;
    std::vector<gpu::GpuMaterialTexture> materialTextures;
    std::vector<std::uint32_t> texturePixels;
    glm::vec4 ambient{0.0f};
    // --precision fp64 only (else empty): the same spheres and vertex positions in double,
    // which the GPU then gets instead of the float ones; a position's w is its material
    // index as a double. Vertices are shared only when their doubles are equal.
    std::vector<glm::dvec4> spheres64;
    std::vector<glm::dvec4> vertexPositions64;
    HierarchyReport hierarchy; // packScene only
    // packScene only: slot k of the sphere (triangle) arrays holds the file's sphere
    // (triangle) number sphereOrder[k] (triangleOrder[k]). Kept on the host, for the pixel
    // story's file indices and lines (host/render/pixel_story.h); never uploaded.
    std::vector<std::uint32_t> sphereOrder;
    std::vector<std::uint32_t> triangleOrder;
};

// The triangle and vertex arrays in the layout the kernel reads (shaders/shared.h,
// BINDING_TRIANGLE_CORNERS on): derived from a PackedScene at upload, in its triangle order.
// Traversal fetches a triangle's three corners, independent of each other, where the
// vertex indices and then the positions were two dependent fetches; the positions are not
// uploaded at all, shading reading the hit triangle's corners.
struct GpuTriangleArrays {
    // Three per triangle: the corner's position (fp32: the float one; empty in fp64), w the
    // flat patch (corner 0) or the vertex index of corner 0 (corner 1) and 1 (corner 2), as
    // the uint's bits.
    std::vector<glm::vec4> corners;
    std::vector<glm::dvec4> corners64;          // fp64 only: the same, doubles, w exact
    std::vector<std::uint32_t> lastVertices;    // per triangle, the vertex index of corner 2
    std::vector<glm::vec4> normalsAndMaterials; // per vertex: normal xyz, material bits in w
};
GpuTriangleArrays gpuTriangleArrays(const PackedScene& packed);

// The same arrays written straight into memory (the device buffer at upload, so that no
// host copy of them exists): each array's size in bytes, and the write of its bytes.
struct GpuTriangleArrayBytes {
    std::size_t corners = 0;             // vec4 (fp32) or dvec4 (fp64) per corner
    std::size_t lastVertices = 0;        // uint per triangle
    std::size_t normalsAndMaterials = 0; // vec4 per vertex
};
GpuTriangleArrayBytes gpuTriangleArrayBytes(const PackedScene& packed);
void writeTriangleCorners(const PackedScene& packed, void* destination);
void writeLastVertices(const PackedScene& packed, void* destination);
void writeNormalsAndMaterials(const PackedScene& packed, void* destination);

// What the GPU needs: the scene packed in the hierarchy's leaf order, with the hierarchy
// itself only when it pays (acceleration, useHierarchy). The leaf order is used either
// way, so both paths see the same primitive order and break ties alike.
// packSceneInFileOrder, then arrangeForHierarchy.
PackedScene packScene(const Scene& scene, Acceleration acceleration, Precision precision);

// The second step of packScene, which needs the scene no more: the hierarchy built over
// the packed primitives and the packed scene put in its leaf order (the "hierarchy" phase
// and the rest of "pack").
void arrangeForHierarchy(PackedScene& packed, Acceleration acceleration);

// The first step of packScene: spheres and triangles in file order, materials and
// vertices shared; no hierarchy. finishPacking(readForPacking(scene, precision)).
PackedScene packSceneInFileOrder(const Scene& scene, Precision precision = Precision::Fp32);

// packSceneInFileOrder in two halves, for a caller that lets the scene's geometry go
// between them (createRendererReleasingGeometry): readForPacking takes all that packing
// needs of the scene (its corners as candidate vertices, its spheres, materials, textures
// and lights), and finishPacking makes the packed scene of that alone.
struct PackingInput; // scene_packing.cpp's
struct PackingInputDeleter {
    void operator()(PackingInput* input) const;
};
using PackingInputPtr = std::unique_ptr<PackingInput, PackingInputDeleter>;
PackingInputPtr readForPacking(const Scene& scene, Precision precision);
PackedScene finishPacking(PackingInputPtr input);

// The lights as the GPU holds them (position, colour), in order.
std::vector<gpu::GpuLight> packLights(const std::vector<Light>& lights);

// The material index of vertex v, from its position's w.
std::uint32_t vertexMaterial(const PackedScene& packed, std::size_t v);

// The box of every sphere, then of every triangle, slightly enlarged (see scene_packing.cpp);
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
