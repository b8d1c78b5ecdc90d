// The trace kernel's compute pipeline and the layout of what it binds.
#pragma once

#include "gpu/context.h"
#include "packing/kernel_choices.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

// Values for the kernel's specialization constants (SPEC_* in shaders/shared.h). The
// driver compiles the kernel for them, so a path they switch off costs nothing; on
// lavapipe a branch on a push constant would still run both sides, masked.
// The defaults are the general kernel: robust methods, any scene content.
struct TraceSpecialization {
    VkBool32 useHierarchy = VK_FALSE;            // walk the BVH rather than test every primitive
    VkBool32 hasSpheres = VK_TRUE;               // the scene holds spheres
    VkBool32 hasTriangles = VK_TRUE;             // the scene holds triangles
    std::uint32_t sampler = SAMPLER_R2;          // --sampler
    VkBool32 stableSphereTest = VK_TRUE;         // --sphere-test stable (else naive)
    VkBool32 watertightTriangles = VK_TRUE;      // --triangle-test watertight (else mt)
    std::uint32_t rayOffset = RAY_OFFSET_SCALED; // --offset
    VkBool32 hasMirrors = VK_TRUE;  // some material has ks > 0 and depth > 0: reflection loop
    VkBool32 hasSpecular = VK_TRUE; // some material has ks > 0: the Phong highlight
    // Some material's mirror share is not 1: the mirror weight is ks times it (else ks).
    VkBool32 hasMirrorShares = VK_TRUE;
    VkBool32 hasTextures = VK_TRUE; // some material samples a texture (SPEC_HAS_TEXTURES)
    // Shadow rays from the shifted point (--terminator, SPEC_SHIFT_SHADOW_ORIGIN).
    VkBool32 shiftShadowOrigin = VK_FALSE;
    VkBool32 texelReads = VK_TRUE; // hot arrays through texel buffers (else storage buffers)
    // Triangles as vertex indices and shared positions (SPEC_INDEXED_TRIANGLES), else corners.
    VkBool32 indexedTriangles = VK_FALSE;
    // A small scene's spheres baked in (shaders/baked_spheres.glsl), and the sphere and
    // light counts the kernel is then compiled for.
    VkBool32 bakedSpheres = VK_FALSE;
    std::uint32_t bakedSphereCount = 0;
    std::uint32_t bakedLightCount = 0;
    // The recording kernel of --pixel (host/render/pixel_story.h): one pixel, into the story.
    VkBool32 recordPixel = VK_FALSE;
    VkBool32 floatOutput = VK_FALSE; // averages also to BINDING_ACCUMULATION (-o .pfm/.exr)
    VkBool32 outputPart = VK_FALSE;  // the output image is a --crop part (SPEC_OUTPUT_PART)
    // The traversal stack's entries: the hierarchy's depth (shaders/bvh.glsl, traverseBvh).
    std::uint32_t stackDepth = BVH_STACK_SIZE;
    // --count-work (hidden): the hierarchy's work counted into GpuKernelStatus.
    VkBool32 countWork = VK_FALSE;
};

// The descriptor type of a binding of shaders/shared.h, as render/bindings.h's table gives it.
VkDescriptorType bindingDescriptorType(std::uint32_t binding);

// The method choices' part of the specialization (the scene's part is left as given).
void applyKernelChoices(TraceSpecialization& specialization, const KernelChoices& choices);

// glslang's preamble for a precision: "#define RT_FP64 1" for fp64 (shaders/precision.glsl).
std::string precisionPreamble(Precision precision);

// The key of the cached SPIR-V: the compiler, its settings, the precision's preamble and
// every embedded source, so fp32 and fp64 kernels never share a file.
std::uint64_t traceSourceKey(Precision precision);

struct TracePipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Builds the pipeline from SPIR-V of shaders/trace.comp; cache may be VK_NULL_HANDLE.
TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv,
                                  VkPipelineCache cache = VK_NULL_HANDLE,
                                  TraceSpecialization specialization = {});

// Where the kernel's sources come from, and where compiled results are kept.
struct KernelSource {
    std::filesystem::path shaderDirectory; // --shader-dir: the user's files; empty: embedded
    std::filesystem::path cacheDirectory;  // SPIR-V and driver cache; empty: none (--no-cache)
};

// The trace kernel, compiled and specialised: the SPIR-V handed to the driver has the
// specialization's values frozen in and the code they switch off removed
// (host/gpu/spirv_specializer.h). Embedded sources go through the on-disk cache in
// cacheDirectory (host/gpu/pipeline_cache.h): glslang runs only when no SPIR-V is cached
// for them, SPIRV-Tools only when no specialised SPIR-V is cached for them and the
// specialization, and the driver is offered its pipeline cache under the same key. A shader folder
// changes under us, so its kernel is never cached, and its compile errors name each file with the
// folder in front. Throws ShaderCompileError when the kernel does not compile.
TracePipeline loadTracePipeline(const Context& context, const KernelSource& source,
                                TraceSpecialization specialization = {},
                                Precision precision = Precision::Fp32);

void destroyTracePipeline(const Context& context, TracePipeline& pipeline);
