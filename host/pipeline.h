// The trace kernel's compute pipeline and the layout of what it binds.
#pragma once

#include "context.h"

#include <cstdint>
#include <filesystem>
#include <vector>

// Values for the kernel's specialization constants (SPEC_* in shaders/shared.h). The
// driver compiles the kernel for them, so a path they switch off costs nothing; on
// lavapipe a branch on a push constant would still run both sides, masked.
struct TraceSpecialization {
    VkBool32 useHierarchy = VK_FALSE; // walk the BVH rather than test every primitive
    VkBool32 hasSpheres = VK_TRUE;    // the scene holds spheres
    VkBool32 hasTriangles = VK_TRUE;  // the scene holds triangles
};

struct TracePipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Builds the pipeline from SPIR-V of shaders/trace.comp; cache may be VK_NULL_HANDLE.
TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv,
                                  VkPipelineCache cache = VK_NULL_HANDLE,
                                  TraceSpecialization specialization = {});

// The trace kernel from the embedded sources, through the on-disk cache in
// cacheDirectory (host/pipeline_cache.h): glslang runs only when no SPIR-V is cached
// for these sources, and the driver is offered its pipeline cache. An empty
// cacheDirectory compiles everything and writes nothing.
TracePipeline loadTracePipeline(const Context& context,
                                const std::filesystem::path& cacheDirectory,
                                TraceSpecialization specialization = {});

void destroyTracePipeline(const Context& context, TracePipeline& pipeline);
