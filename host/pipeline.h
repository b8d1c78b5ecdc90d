// The trace kernel's compute pipeline and the layout of what it binds.
#pragma once

#include "context.h"

#include <cstdint>
#include <filesystem>
#include <vector>

struct TracePipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Builds the pipeline from SPIR-V of shaders/trace.comp; cache may be VK_NULL_HANDLE.
TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv,
                                  VkPipelineCache cache = VK_NULL_HANDLE);

// The trace kernel from the embedded sources, through the on-disk cache in
// cacheDirectory (host/pipeline_cache.h): glslang runs only when no SPIR-V is cached
// for these sources, and the driver is offered its pipeline cache. An empty
// cacheDirectory compiles everything and writes nothing.
TracePipeline loadTracePipeline(const Context& context,
                                const std::filesystem::path& cacheDirectory);

void destroyTracePipeline(const Context& context, TracePipeline& pipeline);
