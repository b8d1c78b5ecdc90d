// The trace kernel's compute pipeline and the layout of what it binds.
#pragma once

#include "context.h"

#include <cstdint>
#include <vector>

struct TracePipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// Builds the pipeline from SPIR-V of shaders/trace.comp.
TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv);

void destroyTracePipeline(const Context& context, TracePipeline& pipeline);
