// The single definition of everything the host and the shaders must agree on:
// binding numbers, workgroup size, limits and the layout of every GPU struct.
// Included by C++ (host/scene_gpu.h) and by GLSL (trace.comp).
//
// Rules for the structs (std430): only vec4, uvec4 and scalars in groups of four,
// never vec3 (std430 pads it to 16 bytes, glm::vec3 is 12), never bool.
// The C++ side pins every size with static_assert in host/scene_gpu.cpp.
#ifndef RAYTRACER_SHARED_H
#define RAYTRACER_SHARED_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using uint = std::uint32_t;
#define GPU_NAMESPACE_END }
#else
#define GPU_NAMESPACE_END
#endif

// Threads per workgroup. lavapipe runs one workgroup per thread-pool task, so a
// workgroup needs 64 or more invocations to keep its 8-wide SIMD lanes busy.
#define WORKGROUP_SIZE_X 8
#define WORKGROUP_SIZE_Y 8

// The deepest reflection recursion the shader supports (--depth is capped here).
#define MAX_DEPTH 64

// Descriptor set 0. Each scene array has its own binding; all of them are
// sub-ranges of one device buffer (see host/scene_gpu.cpp).
#define BINDING_OUTPUT_IMAGE 0     // rgba8 storage image the kernel writes
#define BINDING_SPHERES 1          // vec4 per sphere: centre xyz, radius w
#define BINDING_SPHERE_MATERIALS 2 // uint per sphere: index into materials
#define BINDING_TRIANGLES 3        // 3 uint per triangle: indices into the vertex arrays
#define BINDING_VERTEX_POSITIONS 4 // vec4 per vertex: position xyz, w unused
#define BINDING_VERTEX_NORMALS 5   // vec4 per vertex: normal xyz as given, w unused
#define BINDING_VERTEX_MATERIALS 6 // uint per vertex: index into materials
#define BINDING_MATERIALS 7        // GpuMaterial per distinct material
#define BINDING_LIGHTS 8           // GpuLight per light
#define BINDING_COUNT 9

// A material, shared by every sphere and vertex that uses it. 32 bytes.
struct GpuMaterial {
    vec4 diffuseShininess; // kd in xyz, Phong exponent in w
    vec4 specular;         // ks in xyz (also the mirror weight), w unused
};

// A point light. 32 bytes.
struct GpuLight {
    vec4 position; // xyz, w unused
    vec4 color;    // rgb, w unused
};

// Per-dispatch parameters, passed as push constants (at most 128 bytes).
struct GpuFrameParams {
    vec4 background; // rgb colour of rays that hit nothing, w unused
    vec4 ambient;    // rgb ambient light added once per shading point, w unused
    vec4 camera;     // x: aspect * tan(fov/2), y: tan(fov/2), zw unused
    uvec4 image;     // x: width, y: height, z: samples per pixel, w: reflection depth
    uvec4 counts;    // x: spheres, y: triangles, z: lights, w unused
    uvec4 tile;      // xy: first pixel of this dispatch, zw unused
};

GPU_NAMESPACE_END

#endif
