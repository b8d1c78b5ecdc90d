// The single definition of everything the host and the shaders must agree on:
// binding numbers, workgroup size, limits and the layout of every GPU struct.
// Included by GLSL (trace.comp) and by the C++ that needs a binding, a limit or a GPU struct:
// the packer (host/packing/), the renderer (host/render/), the options (host/cli/) and tests.
//
// Rules for the structs (std430): only vec4, uvec4 and scalars in groups of four,
// never vec3 (std430 pads it to 16 bytes, glm::vec3 is 12), never bool.
// The C++ side pins every size with static_assert in host/packing/scene_packing.cpp.
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

// The widest and tallest image (--width, --height): a pixel's column and row fit 16 bits
// (GpuFrameParams packs a region's origin so), and in float a coordinate keeps sample
// positions within 1/128 of a pixel (camera.glsl). A poster larger than the device's image
// limit renders in --crop parts (RenderSettings::crop).
#define MAX_IMAGE_SIDE 65536

// Descriptor set 0. Each scene array has its own binding; all of them are
// sub-ranges of one device buffer (host/render/scene_upload.cpp lays them out). What each
// binding is (its descriptor type, what fills it) is host/render/bindings.cpp's table.
#define BINDING_OUTPUT_IMAGE 0     // rgba8 storage image the kernel writes
#define BINDING_SPHERES 1          // vec4 per sphere: centre xyz, radius w
#define BINDING_SPHERE_MATERIALS 2 // uint per sphere: index into materials
// Triangles, in leaf order, in one of two layouts (SPEC_INDEXED_TRIANGLES; the other's
// bindings see the zeroed slot). Corners (host/packing/scene_packing.h, gpuTriangleArrays):
// traversal reads a triangle's three corners and nothing else, three independent fetches;
// the vertex indices that shading needs (normals, materials) are read for the hit alone.
// Indexed (BINDING_TRIANGLE_VERTICES on): a triangle is its vertex indices, each vertex's
// position stored once, a dependent fetch more for fewer bytes where vertices are shared.
// Corners: rvec4 per corner, three per triangle: the corner's position xyz, the very floats
// (doubles in fp64) that the tests compute with; w: corner 0 the triangle's flat patch,
// corners 1 and 2 the vertex indices of corners 0 and 1 (uint bits in fp32, exact
// integers in fp64).
#define BINDING_TRIANGLE_CORNERS 3
#define BINDING_TRIANGLE_LAST_VERTICES 4 // uint per triangle: the vertex index of its corner 2
// vec4 per vertex: the normal xyz as given, w the index of its material (uint bits).
#define BINDING_VERTEX_NORMALS 5
#define BINDING_MATERIALS 6    // GpuMaterial per distinct material
#define BINDING_LIGHTS 7       // GpuLight per light
#define BINDING_BVH_NODES 8    // GpuBvhNode per hierarchy node, depth first (host/packing/bvh.h)
#define BINDING_ACCUMULATION 9 // vec4 per pixel, row major: the window's running sum of samples
// The arrays read inside loops (traversal, primitives, bounces, lights), again, as uniform
// texel buffers: views of the same ranges (SPEC_TEXEL_READS picks them over the above).
// On lavapipe a texel fetch is a gather, where a storage-buffer load inside control flow
// is a loop over the lanes (docs/performance.md).
#define BINDING_SPHERE_TEXELS 10      // RGBA32F view of BINDING_SPHERES
#define BINDING_CORNER_TEXELS 11      // RGBA32F view of BINDING_TRIANGLE_CORNERS (not fp64)
#define BINDING_LAST_VERTEX_TEXELS 12 // R32UI view of BINDING_TRIANGLE_LAST_VERTICES
#define BINDING_BVH_NODE_TEXELS 13    // RGBA32F view of BINDING_BVH_NODES, 4 texels per node
#define BINDING_NORMAL_TEXELS 14      // RGBA32F view of BINDING_VERTEX_NORMALS
#define BINDING_MATERIAL_TEXELS 15    // RGBA32F view of BINDING_MATERIALS, 2 texels per material
#define BINDING_SPHERE_MATERIAL_TEXELS 16 // R32UI view of BINDING_SPHERE_MATERIALS
#define BINDING_LIGHT_TEXELS 17           // RGBA32F view of BINDING_LIGHTS, 2 texels per light
// The pixel story (docs/pixel_story.md): one GpuPixelStory, written only by the recording
// kernel (SPEC_RECORD_PIXEL); a host-visible buffer the host reads back.
#define BINDING_PIXEL_STORY 18
// What the kernel reports about its own run: one GpuKernelStatus, host-visible, set to zero
// by the host before a submission and read after it.
#define BINDING_KERNEL_STATUS 19
// Textures, bound with content only when the scene has them (SPEC_HAS_TEXTURES; else each is
// the zeroed slot). Sampled by shaders/texture.glsl.
#define BINDING_VERTEX_TEXCOORDS 20  // vec2 per vertex: its texture coordinates u, v (v up)
#define BINDING_MATERIAL_TEXTURES 21 // GpuMaterialTexture per material (materials[]' order)
#define BINDING_TEXTURE_PIXELS 22    // uint per texel of every texture, RGBA8 (unpackUnorm4x8)
#define BINDING_TEXCOORD_TEXELS 23   // RG32F view of BINDING_VERTEX_TEXCOORDS
#define BINDING_MATERIAL_TEXTURE_TEXELS 24 // RGBA32UI view of BINDING_MATERIAL_TEXTURES
#define BINDING_TEXTURE_PIXEL_TEXELS 25    // R32UI view of BINDING_TEXTURE_PIXELS
// Indexed triangles: uvec4 per triangle, its vertices' indices in xyz and its flat patch in w;
// rvec4 per vertex, its position xyz (the same floats or doubles as a corner's; w its
// material's index, which the kernel reads from BINDING_VERTEX_NORMALS instead).
#define BINDING_TRIANGLE_VERTICES 26
#define BINDING_VERTEX_POSITIONS 27
#define BINDING_TRIANGLE_VERTEX_TEXELS 28 // RGBA32UI view of BINDING_TRIANGLE_VERTICES
#define BINDING_POSITION_TEXELS 29        // RGBA32F view of BINDING_VERTEX_POSITIONS (not fp64)
#define BINDING_COUNT 30

// Specialization constant ids (host/render/trace_pipeline.h, TraceSpecialization): bool unless
// marked uint.
#define SPEC_USE_HIERARCHY 0 // walk the BVH (else test every primitive: scenes too small for one)
#define SPEC_HAS_SPHERES 1   // the scene holds spheres (else their code is compiled out)
#define SPEC_HAS_TRIANGLES 2 // the scene holds triangles (likewise)
// The method choices of the command line (host/packing/kernel_choices.h), and more of the scene.
#define SPEC_SAMPLER 3              // uint, SAMPLER_*: sample positions inside a pixel (--sampler)
#define SPEC_STABLE_SPHERE_TEST 4   // bool: Ray Tracing Gems ch. 7, else the textbook quadratic
#define SPEC_WATERTIGHT_TRIANGLES 5 // bool: Woop et al. 2013, else Moller-Trumbore
#define SPEC_RAY_OFFSET 6           // uint, RAY_OFFSET_*: secondary-ray origins (--offset)
#define SPEC_HAS_MIRRORS 7          // bool: some material has ks > 0 and --depth > 0
#define SPEC_HAS_SPECULAR 8         // bool: some material has ks > 0 (else no Phong highlight)
// bool: read the scene through the texel buffers (else through the storage buffers: an
// array beyond maxTexelBufferElements, or --storage-reads); fp64's doubles never are.
#define SPEC_TEXEL_READS 9
// Small scenes' spheres baked in (shaders/baked_spheres.glsl): whether they are, and the
// sphere and light counts (uint) that the kernel is then compiled for.
#define SPEC_BAKED_SPHERES 10
#define SPEC_BAKED_SPHERE_COUNT 11
#define SPEC_BAKED_LIGHT_COUNT 12
// bool: the recording kernel of --pixel (docs/pixel_story.md): dispatched for one pixel, it
// writes what it computes into BINDING_PIXEL_STORY instead of the image.
#define SPEC_RECORD_PIXEL 13
// bool: also write each pixel's average before the 8-bit rounding to BINDING_ACCUMULATION
// (headless, one pass: -o out.pfm|out.exr).
#define SPEC_FLOAT_OUTPUT 14
// uint: the entries of the traversal stack, the hierarchy's depth (1 to BVH_STACK_SIZE).
#define SPEC_STACK_DEPTH 15
// bool: count the hierarchy's work into GpuKernelStatus (--count-work, hidden): a measure of
// a kernel change that no timing noise moves.
#define SPEC_COUNT_WORK 16
// bool: some material's mirror share (GpuMaterial's specular.w) is not 1, so the mirror
// weight is not simply ks (a highlight without a mirror: MTL illum 2).
#define SPEC_HAS_MIRROR_SHARES 17
// bool: shadow rays leave a smooth-shaded triangle from its hit point moved onto the vertex
// normals' tangent planes (Hanika, "Hacking the Shadow Terminator", Ray Tracing Gems II):
// --terminator, on for OBJ models by default, off for scene files.
#define SPEC_SHIFT_SHADOW_ORIGIN 18
// bool: some material samples a texture (else texture coordinates and texels are compiled out).
#define SPEC_HAS_TEXTURES 19
// bool: the output image holds a part of the full image (headless --crop), placed by
// GpuFrameParams; else all of it, and the kernel is the one without the part's arithmetic.
#define SPEC_OUTPUT_PART 20
// bool: the triangles are indexed (BINDING_TRIANGLE_VERTICES and BINDING_VERTEX_POSITIONS),
// else corners (BINDING_TRIANGLE_CORNERS and BINDING_TRIANGLE_LAST_VERTICES).
#define SPEC_INDEXED_TRIANGLES 21
// The most spheres baked in: the closest-hit loop over them is unrolled, one test each.
#define MAX_BAKED_SPHERES 15u
#define RAY_OFFSET_FIXED 0u       // 1e-4 along the normal
#define RAY_OFFSET_SCALED 1u      // Waechter-Binder, scale-relative
#define RAY_OFFSET_ERROR_BOUND 2u // the hit point's rounding-error bound, own triangle skipped
#define SAMPLER_GRID 0u
#define SAMPLER_STRATIFIED 1u
#define SAMPLER_R2 2u

// The bounding volume hierarchy (host/packing/bvh.cpp builds it, shaders/bvh.glsl walks it).
// Traversal keeps the far child of each interior node on a fixed stack of this many
// entries, at most one per level, so the builder keeps every leaf within this depth.
#define BVH_STACK_SIZE 32
// A child reference, one uint (GpuBvhNode's ...MinAndRef.w): an interior child's node index,
// below BVH_LEAF; a leaf's BVH_LEAF | count << BVH_COUNT_SHIFT | first primitive, with
// BVH_LEAF_SPHERES when they are spheres (every leaf holds one kind). One uint per
// reference keeps the traversal stack to one array (shaders/bvh.glsl), which lavapipe keeps
// in memory, each push and pop a per-lane access per array (docs/performance.md).
#define BVH_LEAF 0x80000000u
#define BVH_LEAF_SPHERES 0x40000000u
#define BVH_COUNT_SHIFT 26
#define BVH_MAX_LEAF_COUNT 15u         // a leaf's count field: 4 bits
#define BVH_FIRST_MASK 0x03ffffffu     // a leaf's first primitive: 26 bits
#define BVH_MAX_PRIMITIVES 0x04000000u // so every slot fits the first-primitive field

// A material, shared by every sphere and vertex that uses it. 32 bytes.
struct GpuMaterial {
    vec4 diffuseShininess; // kd in xyz, Phong exponent in w
    vec4 specular;         // ks in xyz; w: the share of ks that is the mirror weight
};

// Where a material's texture lies in BINDING_TEXTURE_PIXELS. 16 bytes.
struct GpuMaterialTexture {
    uvec4 placement; // x: its first texel, y: width, z: height (0: the material has none),
                     // w unused. Rows top first, each left to right.
};

// A point light. 32 bytes.
struct GpuLight {
    vec4 position; // xyz, w unused
    vec4 color;    // rgb, w unused
};

// An interior node of the hierarchy, holding the boxes of both its children (Aila & Laine,
// "Understanding the Efficiency of Ray Traversal on GPUs", HPG 2009). 64 bytes, one cache
// line: a traversal step fetches one node and tests both child boxes. Leaves are no nodes
// of their own; a child's reference says where its primitives are, so they are tested
// without a further fetch. The uints in the .w components are stored with their bit
// patterns (std::bit_cast on the host, floatBitsToUint in GLSL).
// Each child's reference is in ...MinAndRef.w (the uint's bits): an interior child's node
// index, or a leaf's count and first primitive, whose primitives are consecutive in the
// sphere or triangle arrays (the packer stores them in leaf order). ...Max.w is unused (0).
struct GpuBvhNode {
    vec4 leftMinAndRef;  // left child's box min xyz; w: its reference
    vec4 leftMax;        // left child's box max xyz; w unused
    vec4 rightMinAndRef; // the same for the right child
    vec4 rightMax;
};

// Per-dispatch parameters, passed as push constants (at most 128 bytes).
struct GpuFrameParams {
    // With SPEC_OUTPUT_PART (headless --crop, whose output image is the crop's size), the
    // part of the full image the output image holds, in the w of three vectors (the uints'
    // bits): background.w and ambient.w its end, x and y (one past its last pixel),
    // cameraOrigin.w its first pixel, x | y << 16 (both below MAX_IMAGE_SIDE).
    vec4 background;        // rgb colour of rays that hit nothing
    vec4 ambient;           // rgb ambient light added once per shading point
    vec4 camera;            // x: aspect * tan(fov/2), y: tan(fov/2), z: the stride of the
                            // workgroup rows' order over the dispatch's rows of tiles (the
                            // uint's bits; host/packing/workgroup_order.h), w:
                            // LOOP_PROBE_ITERATIONS (the uint's bits; trace.comp, main)
    vec4 cameraOrigin;      // the eye in world space: xyz
    vec4 cameraOrientation; // unit quaternion xyzw, camera space to world (0,0,0,1 for the default
                            // camera)
    uvec4 image;            // x: width, y: height of the full image, z: samples per pixel n
                            // (sampleOffset's n), w: reflection depth
    uvec4 counts;           // x: spheres, y: triangles, z: lights, w: sampling seed (--seed)
    // xy: first pixel of this dispatch. zw: the samples it adds: z the index of the first,
    // w how many; w == 0 traces all image.z samples in one pass (headless). With w > 0
    // (the window's progressive view) the sum of samples 0..z-1 is read from and the sum
    // of 0..z+w-1 written to BINDING_ACCUMULATION, and the output shows their average.
    uvec4 dispatch;
};

// The pixel story (--pixel, the window's I key; docs/pixel_story.md): what the recording
// kernel computed for sample 0 of one pixel, bounce by bounce. Primitive indices are the
// kernel's slots (leaf order); the host maps them to the file's order and lines.
#define MAX_STORY_LIGHTS 16u   // lights recorded per bounce; the rest are counted, not recorded
#define STORY_LIGHT_BEHIND 0u  // N.L <= 0 (also a light at the point itself): skipped
#define STORY_LIGHT_BLOCKED 1u // the shadow ray hit something before the light
#define STORY_LIGHT_LIT 2u
// How a bounce ends its sample's ray, or goes on (GpuStoryBounce.hit.w).
#define STORY_NEXT_REFLECT 0u         // a mirror ray follows: the next bounce
#define STORY_NEXT_MISS 1u            // the ray hit nothing: the background
#define STORY_NEXT_NO_MIRROR 2u       // ks == 0: the local colour ends it
#define STORY_NEXT_DEPTH 3u           // --depth reflections reached (or 0): likewise
#define STORY_NEXT_ZERO_THROUGHPUT 4u // the ks product is 0: nothing further can contribute

// One light at one bounce. 32 bytes.
struct GpuStoryLight {
    vec4 contribution; // rgb: Lc (kd N.L + ks max(R.V, 0)^shininess) when lit, else 0; w: N.L
    uvec4 shadow;      // x: STORY_LIGHT_*; blocked: y the blocker's hit kind (nearest one on
                       // the shadow ray; 0 unknown), z its slot; w unused
};

// One ray of the sample and what it met. 672 bytes.
struct GpuStoryBounce {
    vec4 origin;           // ray origin xyz; w: t of the hit (0 for a miss)
    vec4 direction;        // unit ray direction xyz; w unused
    uvec4 hit;             // x: kind (0 none, 1 sphere, 2 triangle), y: slot, z: lights
                           // recorded, w: STORY_NEXT_*
    vec4 barycentric;      // triangles: the weights of vertices 0, 1, 2; w unused
    vec4 normal;           // shading normal xyz, facing the ray; w unused
    vec4 diffuseShininess; // kd xyz as shaded (interpolated on a triangle), shininess w
    vec4 specular;         // ks xyz (also the mirror weight); w unused
    vec4 local;            // local Phong colour rgb (ambient + lights); a miss: the background
    vec4 throughput;       // rgb: this bounce's weight in the sample, the product of earlier ks
    vec4 color;            // rgb: the sample's colour so far, this bounce's share included
    GpuStoryLight lights[MAX_STORY_LIGHTS];
};

// The passes of the kernel's last loop, which tells whether the driver ended its loops early
// (trace.comp, main); given in GpuFrameParams.camera.w, so that the compiler cannot unroll it.
// Three, not two: the compiler runs a loop's first pass before the loop proper, and a driver
// that ends loops early still lets the loop proper run one pass.
#define LOOP_PROBE_ITERATIONS 3u

// The kernel's report on a submission (BINDING_KERNEL_STATUS).
// cutShortInvocations: invocations whose loops were ended early by the driver, not by the
// trace. Mesa's CPU driver (llvmpipe, lavapipe) allows every invocation 65535 loop
// iterations in all, counted over all of its loops together; past that each loop stops at
// its next test and the pixel's value is wrong (samples lost, a traversal cut off). The
// kernel notices (trace.comp, main) and the host then traces fewer samples per dispatch
// (host/render/sample_passes.h). 16 bytes.
// nodeVisits and leafPrimitiveTests (with SPEC_COUNT_WORK only): the hierarchy's interior
// nodes visited (two boxes tested each) and the primitives tested in its leaves, summed over
// the submission's invocations, modulo 2^32 (small images stay far below).
struct GpuKernelStatus {
    uint cutShortInvocations;
    uint nodeVisits;
    uint leafPrimitiveTests;
    uint unused;
};

// The whole story of one pixel: its sample 0's tree and the pixel's final value.
struct GpuPixelStory {
    uvec4 counts;      // x: bounces recorded, y: lights in the scene, z: samples, w: 1 once written
    vec4 sampleOffset; // xy: sample 0's (u, v) inside the pixel; zw unused
    vec4 sampleColor;  // rgb: sample 0's colour before the clamp; w unused
    vec4 pixelColor;   // rgb: the average of the clamped samples (the running sum between the
                       // passes of a pixel traced in several dispatches); w unused
    uvec4 pixelLevel;  // rgb: the 8-bit levels written to the image; w unused
    GpuStoryBounce bounces[MAX_DEPTH + 1];
};

GPU_NAMESPACE_END

#endif
