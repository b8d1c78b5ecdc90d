#version 460
// The ray tracing kernel: one invocation per pixel of the current dispatch. Whitted-style
// tracing of the model of docs/model.md: primary ray, Phong shading with hard shadows, mirror
// reflections as an iterative loop with a throughput, clamped samples averaged, written as
// an exact 8-bit value.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_spirv_intrinsics : require // NMin and NMax (bvh.glsl)

#include "shared.h"
#include "precision.glsl"

layout(local_size_x = WORKGROUP_SIZE_X, local_size_y = WORKGROUP_SIZE_Y, local_size_z = 1) in;

// What the scene needs, as specialization constants: the driver compiles the kernel for
// their values, so code for what is absent costs nothing. lavapipe runs both sides of a
// branch on a uniform value, masked: with the choice in a push constant, the unused
// hierarchy code made the brute-force path 50% slower on small scenes, and the sphere
// code in every leaf slowed triangle-only scenes by 10%.
// Whether closestHit and anyHit walk the hierarchy (bvh.glsl) or test every primitive.
layout(constant_id = SPEC_USE_HIERARCHY) const bool useHierarchy = false;
// Whether the scene holds spheres, and triangles.
layout(constant_id = SPEC_HAS_SPHERES) const bool sceneHasSpheres = true;
layout(constant_id = SPEC_HAS_TRIANGLES) const bool sceneHasTriangles = true;
// Whether some material has ks > 0 and --depth > 0 (else no reflection loop), and whether
// some material has ks > 0 (else no highlight).
layout(constant_id = SPEC_HAS_MIRRORS) const bool sceneHasMirrors = true;
layout(constant_id = SPEC_HAS_SPECULAR) const bool sceneHasSpecular = true;
// Whether some material's mirror share is not 1 (a highlight without a mirror): else the
// mirror weight is ks itself.
layout(constant_id = SPEC_HAS_MIRROR_SHARES) const bool sceneHasMirrorShares = true;
// Whether some material samples a texture (texture.glsl).
layout(constant_id = SPEC_HAS_TEXTURES) const bool sceneHasTextures = false;
// Whether shadow rays leave from the hit point moved as Hanika's terminator fix does (shade.glsl).
layout(constant_id = SPEC_SHIFT_SHADOW_ORIGIN) const bool shiftShadowOrigin = false;

// The method choices of the command line (host/packing/kernel_choices.h); the defaults are the
// robust methods, and the unchosen method is compiled out.
layout(constant_id = SPEC_SAMPLER) const uint samplerKind = SAMPLER_R2;
layout(constant_id = SPEC_STABLE_SPHERE_TEST) const bool stableSphereTest = true;
layout(constant_id = SPEC_WATERTIGHT_TRIANGLES) const bool watertightTriangles = true;
layout(constant_id = SPEC_RAY_OFFSET) const uint rayOffsetKind = RAY_OFFSET_ERROR_BOUND;
// Whether the loops read the scene through texel buffers (scene_reads.glsl); the host turns
// it off for an array beyond maxTexelBufferElements and for --storage-reads.
layout(constant_id = SPEC_TEXEL_READS) const bool texelReads = true;
// A small scene's spheres baked in (baked_spheres.glsl), and its sphere and light counts
// fixed at compile time.
layout(constant_id = SPEC_BAKED_SPHERES) const bool bakedSpheres = false;
layout(constant_id = SPEC_BAKED_SPHERE_COUNT) const uint bakedSphereCount = 0u;
layout(constant_id = SPEC_BAKED_LIGHT_COUNT) const uint bakedLightCount = 0u;
// The hierarchy's depth (its deepest leaf, at least 1): the entries of the traversal stack
// (bvh.glsl), which costs a select per entry on every push and pop on lavapipe.
layout(constant_id = SPEC_STACK_DEPTH) const uint stackDepth = BVH_STACK_SIZE;
// The recording kernel of --pixel (pixel_story.glsl): one pixel, into `story`, not the image.
layout(constant_id = SPEC_RECORD_PIXEL) const bool recordPixel = false;
// -o out.pfm|out.exr: each pixel's average also goes to accumulation[] as floats.
layout(constant_id = SPEC_FLOAT_OUTPUT) const bool floatOutput = false;
// Headless --crop: the output image is a part of the full image (GpuFrameParams places it).
layout(constant_id = SPEC_OUTPUT_PART) const bool outputPart = false;
layout(constant_id = SPEC_INDEXED_TRIANGLES) const bool indexedTriangles = false;
// --count-work (hidden): the hierarchy's work is counted into `status` (GpuKernelStatus).
layout(constant_id = SPEC_COUNT_WORK) const bool countWork = false;
uint nodeVisits = 0u;         // this invocation's, with countWork (bvh.glsl)
uint leafPrimitiveTests = 0u; // likewise

// Camera, counts, image size, samples and depth for this dispatch (see GpuFrameParams).
layout(push_constant) uniform FrameParamsBlock {
    GpuFrameParams params;
};

// The scene's counts, copied from the push constants first thing in main, outside all
// control flow: lavapipe then loads each once for the whole SIMD vector, where a read of
// params in a loop's condition is a load per lane on every iteration. With baked spheres,
// the sphere and light counts are constants.
uint sphereCount, triangleCount, lightCount;

// The RGBA8 UNORM image this kernel writes; the host copies it to the screen or a PNG.
layout(set = 0, binding = BINDING_OUTPUT_IMAGE, rgba8) uniform writeonly image2D outputImage;

// Scene arrays. Their lengths are params.counts, never .length(): an empty array is bound
// to a small dummy buffer.
// Spheres: centre in xyz, radius in w (doubles in fp64, see precision.glsl).
layout(set = 0, binding = BINDING_SPHERES, std430) readonly buffer SphereBuffer {
    rvec4 spheres[];
};
// Per sphere, the index of its material in materials[].
layout(set = 0, binding = BINDING_SPHERE_MATERIALS, std430) readonly buffer SphereMaterialBuffer {
    uint sphereMaterials[];
};
// Triangles in leaf order, as corners (!indexedTriangles) or indexed (below).
// Per triangle corner, three per triangle: its position in xyz, and in w
// corner 0's flat patch (host/packing/flat_patches.h, ray_offset.glsl) or corner 1's and 2's
// vertex indices, the vertices of corners 0 and 1 (shared.h; read with cornerWord).
layout(set = 0, binding = BINDING_TRIANGLE_CORNERS, std430) readonly buffer CornerBuffer {
    rvec4 triangleCorners[];
};
// Per triangle, the vertex index of its corner 2.
layout(set = 0, binding = BINDING_TRIANGLE_LAST_VERTICES, std430) readonly buffer LastVertexBuffer {
    uint triangleLastVertices[];
};
// Indexed triangles (indexedTriangles; else these two are dummies, and with it the two
// above): per triangle its vertices' indices in xyz and its flat patch in w; per vertex
// its position in xyz.
layout(set = 0, binding = BINDING_TRIANGLE_VERTICES, std430) readonly buffer TriangleVertexBuffer {
    uvec4 triangleVertices[];
};
layout(set = 0, binding = BINDING_VERTEX_POSITIONS, std430) readonly buffer PositionBuffer {
    rvec4 vertexPositions[];
};
// Per vertex, its normal as the scene file gives it (maybe unnormalised or zero) in xyz, and
// the index of its material in materials[] in w (the uint's bits; shade.glsl).
layout(set = 0, binding = BINDING_VERTEX_NORMALS, std430) readonly buffer NormalBuffer {
    vec4 vertexNormals[];
};
// The distinct materials of the scene.
layout(set = 0, binding = BINDING_MATERIALS, std430) readonly buffer MaterialBuffer {
    GpuMaterial materials[];
};
// The point lights.
layout(set = 0, binding = BINDING_LIGHTS, std430) readonly buffer LightBuffer {
    GpuLight lights[];
};
// The hierarchy over spheres and triangles, depth first (bound only when useHierarchy is 1).
layout(set = 0, binding = BINDING_BVH_NODES, std430) readonly buffer BvhNodeBuffer {
    GpuBvhNode bvhNodes[];
};
// Textures (texture.glsl), dummies unless sceneHasTextures: per vertex its texture
// coordinates, per material where its texture lies, and every texture's RGBA8 texels.
layout(set = 0, binding = BINDING_VERTEX_TEXCOORDS, std430) readonly buffer TexcoordBuffer {
    vec2 vertexTexcoords[];
};
layout(set = 0, binding = BINDING_MATERIAL_TEXTURES, std430) readonly buffer MaterialTextureBuffer {
    GpuMaterialTexture materialTextures[];
};
layout(set = 0, binding = BINDING_TEXTURE_PIXELS, std430) readonly buffer TexturePixelBuffer {
    uint texturePixels[];
};
// The window's running sum of each pixel's samples (see GpuFrameParams.dispatch); a dummy
// when tracing in one pass.
layout(set = 0, binding = BINDING_ACCUMULATION, std430) buffer AccumulationBuffer {
    vec4 accumulation[];
};

// The kernel's report on its own run (GpuKernelStatus); the host reads it back.
layout(set = 0, binding = BINDING_KERNEL_STATUS, std430) buffer KernelStatusBuffer {
    GpuKernelStatus status;
};

// What the recording kernel computed for one pixel (pixel_story.glsl); the host reads it back.
layout(set = 0, binding = BINDING_PIXEL_STORY, std430) buffer PixelStoryBuffer {
    GpuPixelStory story;
};

#include "scene_reads.glsl"
#include "baked_spheres.glsl"
#include "camera.glsl"
#include "sampling.glsl"
#include "ray_offset.glsl"
#include "intersect.glsl"
#include "bvh.glsl"
#include "pixel_story.glsl"
#include "texture.glsl"
#include "shade.glsl"

// Colour seen along a primary ray: the model's recursion
//   colour = (1 - kr) local + kr colour(reflected)   (local alone when kr == 0 or at depth D)
// with the mirror weight kr (ks times the material's mirror share, docs/model.md),
// unrolled into a loop that carries the product of the kr seen so far (throughput). Each
// pass shades a hit and traces the mirror ray; the miss test closes the loop, where
// lavapipe leaves it (do-while: see traverseBvh in bvh.glsl): with the trace and the test
// at the top, a vector whose rays had all missed still ran the shading once, masked.
vec3 traceRay(Ray ray) {
    uint maxBounces = min(params.image.w, uint(MAX_DEPTH));
    vec3 color = vec3(0.0);
    vec3 throughput = vec3(1.0);
    Hit hit = closestHit(ray);
    uint bounce = 0u;
    storyRay(bounce, ray, hit); // the story's calls record, in the --pixel kernel only
    if (hit.kind != HIT_NONE) {
        do {
            SurfacePoint s = surfaceAt(ray, hit);
            vec3 local = shadePhong(s, -ray.direction);
            storySurface(s.normal, s.kd, s.ks, s.shininess, local, throughput);
            if (!sceneHasMirrors || all(equal(s.kr, vec3(0.0))) || bounce >= maxBounces)
                return storyLast(all(equal(s.kr, vec3(0.0))) ? STORY_NEXT_NO_MIRROR
                                                             : STORY_NEXT_DEPTH,
                                 throughput, local, color + throughput * local);
            color += throughput * (1.0 - s.kr) * local;
            throughput *= s.kr;
            storyReflect(color, throughput);
            // Nothing further can contribute: same result, fewer rays.
            if (all(equal(throughput, vec3(0.0)))) return color;
            ray = reflectedRay(ray, s);
            hit = closestHit(ray);
            ++bounce;
            storyRay(bounce, ray, hit);
        } while (hit.kind != HIT_NONE);
    }
    return storyLast(STORY_NEXT_MISS, throughput, params.background.rgb,
                     color + throughput * params.background.rgb);
}

// Which pixel of its workgroup's 8 x 8 tile an invocation traces. lavapipe runs each 8
// invocations consecutive in x as one 8-wide SIMD vector (whatever the workgroup shape, as
// long as its x size is a multiple of 8), so plain x/y would give each vector a row of 8
// pixels; rearranged, it gets a 4 x 2 block, whose rays stay together longer in the
// hierarchy: fewer SIMD traversal steps, and faster on lavapipe (tools/kernel_costs --baseline).
#if WORKGROUP_SIZE_X != 8 || WORKGROUP_SIZE_Y % 2 != 0
#error "pixelInTile assumes 8-wide workgroups with an even height"
#endif
uvec2 pixelInTile(uvec2 local) {
    return uvec2((local.y % 2u) * 4u + local.x % 4u, (local.y / 2u) * 2u + local.x / 4u);
}

// Which tile of the dispatch (8 x 8 pixels) this workgroup traces: the workgroups of row
// k take the tiles of row (k * stride) mod rows, stride coprime to rows (a permutation), so
// that each worker thread of lavapipe, which takes one contiguous share of the workgroups,
// gets rows from all over the image rather than one band of it
// (host/packing/workgroup_order.h). The remainder comes from a float division, exact for
// these small numbers (workgroup_order.h says why): lavapipe has no vector integer division.
uvec2 tileOfWorkgroup() {
    uint rows = gl_NumWorkGroups.y;
    uint product = gl_WorkGroupID.y * floatBitsToUint(params.camera.z);
    uint quotient = uint((float(product) + 0.5) / float(rows));
    return uvec2(gl_WorkGroupID.x, product - quotient * rows);
}

void main() {
    sphereCount = bakedSpheres ? bakedSphereCount : params.counts.x;
    triangleCount = params.counts.y;
    lightCount = bakedSpheres ? bakedLightCount : params.counts.z;
    loadBakedSpheres();
    uvec2 pixel = params.dispatch.xy +
                  tileOfWorkgroup() * uvec2(WORKGROUP_SIZE_X, WORKGROUP_SIZE_Y) +
                  pixelInTile(gl_LocalInvocationID.xy);
    // The output image holds the full image or (outputPart: --crop) a part of it, from
    // origin to outputEnd (GpuFrameParams); the ray is the full image's pixel's, whatever
    // the part. The --pixel kernel is dispatched with its pixel first, wherever it is: only
    // that invocation records.
    uvec2 outputEnd = params.image.xy;
    uvec2 origin = uvec2(0u);
    if (outputPart && !recordPixel) {
        outputEnd = uvec2(floatBitsToUint(params.background.w), floatBitsToUint(params.ambient.w));
        uint originBits = floatBitsToUint(params.cameraOrigin.w);
        origin = uvec2(originBits & 0xFFFFu, originBits >> 16u);
    }
    if (any(greaterThanEqual(pixel, outputEnd))) return;
    if (recordPixel && any(notEqual(pixel, params.dispatch.xy))) return;
    uvec2 place = pixel - origin;

    // Samples first..end-1 of n. One pass (dispatch.w == 0) sums all n here; otherwise
    // (the window's progressive view, and headless frames split into sample passes) each
    // dispatch adds dispatch.w of them to the running sum in accumulation[], so after the
    // last one it holds the same floats, added in the same order, as the one-pass sum: the
    // image is the one-pass image, bit for bit, however the samples were split.
    uint samples = max(params.image.z, 1u);
    bool progressive = params.dispatch.w != 0u;
    uint first = progressive ? params.dispatch.z : 0u;
    uint end = progressive ? min(first + params.dispatch.w, samples) : samples;
    uint slot = place.y * (outputEnd.x - origin.x) + place.x;
    vec3 sum = vec3(0.0);
    // The story kernel keeps its one pixel's running sum in the story, not in accumulation[],
    // which may hold the window's.
    if (progressive && first != 0u) sum = recordPixel ? storyRunningSum() : accumulation[slot].rgb;
    uint s = first;
    if (s < end) { // do-while: see traverseBvh (bvh.glsl)
        do {
            storyStartSample(s, sampleOffset(pixel, s, samples));
            sum +=
                clamp(storySampleColor(traceRay(cameraRay(pixel, sampleOffset(pixel, s, samples)))),
                      0.0, 1.0);
        } while (++s < end);
    }
    // A loop of LOOP_PROBE_ITERATIONS passes, whose count the compiler cannot see (it comes
    // from the host): a driver that ends loops early once an invocation has used its share
    // (llvmpipe's 65535 loop iterations, GpuKernelStatus) ends this one early too, and the
    // invocation reports itself cut short. An extra pass of the sample loop would say the
    // same, but lavapipe runs a loop's body masked even when no lane is left in it: a whole
    // sample's instructions for nothing.
    uint probe = 0u;
    do {
        ++probe;
    } while (probe < floatBitsToUint(params.camera.w));
    if (probe != LOOP_PROBE_ITERATIONS) atomicAdd(status.cutShortInvocations, 1u);
    if (countWork) {
        atomicAdd(status.nodeVisits, nodeVisits);
        atomicAdd(status.leafPrimitiveTests, leafPrimitiveTests);
    }
    if (recordPixel) { // the story, not the image
        storyPixel(sum, end, samples);
        return;
    }
    if (progressive) accumulation[slot] = vec4(sum, 0.0);
    vec3 average = sum / float(end);
    // Headless only, once the last pass has added its samples: the sum is not needed again.
    if (floatOutput && end == samples) accumulation[slot] = vec4(average, 0.0);
    // floor(c * 255 + 0.5) here, stored as k / 255: the UNORM conversion then gives exactly k
    // whatever the driver's rounding (k / 255 * 255 rounds back to k for every k).
    vec3 level = floor(average * 255.0 + 0.5);
    imageStore(outputImage, ivec2(place), vec4(level / 255.0, 1.0));
}
