#include "pipeline.h"

#include "shared.h"
#include "vk_check.h"

TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv) {
    TracePipeline result;

    // Binding 0 is the output image the kernel writes; every other binding is a
    // read-only range of the scene buffer (see shaders/shared.h for what each holds).
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding = 0; binding < BINDING_COUNT; ++binding) {
        VkDescriptorType type = binding == BINDING_OUTPUT_IMAGE ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                                                                : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings.push_back({binding, type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = static_cast<std::uint32_t>(bindings.size());
    setInfo.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(context.device, &setInfo, nullptr, &result.setLayout));

    VkPushConstantRange pushConstants{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::GpuFrameParams)};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &result.setLayout;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &pushConstants;
    VK_CHECK(vkCreatePipelineLayout(context.device, &layoutInfo, nullptr, &result.layout));

    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = spirv.size() * sizeof(std::uint32_t);
    moduleInfo.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(context.device, &moduleInfo, nullptr, &module));

    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = result.layout;
    VkResult created = vkCreateComputePipelines(context.device, VK_NULL_HANDLE, 1, &pipelineInfo,
                                                nullptr, &result.pipeline);
    // The module is only needed while the pipeline is created.
    vkDestroyShaderModule(context.device, module, nullptr);
    VK_CHECK(created);
    return result;
}

void destroyTracePipeline(const Context& context, TracePipeline& pipeline) {
    if (pipeline.pipeline) vkDestroyPipeline(context.device, pipeline.pipeline, nullptr);
    if (pipeline.layout) vkDestroyPipelineLayout(context.device, pipeline.layout, nullptr);
    if (pipeline.setLayout) vkDestroyDescriptorSetLayout(context.device, pipeline.setLayout, nullptr);
    pipeline = TracePipeline{};
}
