#include "render/trace_pipeline.h"

#include "gpu/cache_file.h"
#include "gpu/pipeline_cache.h"
#include "gpu/shader_compiler.h"
#include "gpu/vk_check.h"
#include "render/kernel_sources.h"
#include "shared.h"

#include <glslang/build_info.h>

#include <cstddef>
#include <iterator>
#include <string>

// Hashed as bytes for the pipeline cache's key: no padding may hide in it.
static_assert(sizeof(TraceSpecialization) == 9 * sizeof(std::uint32_t));

std::string precisionPreamble(Precision precision) {
    return precision == Precision::Fp64 ? "#define RT_FP64 1\n" : "";
}

void applyKernelChoices(TraceSpecialization& specialization, const KernelChoices& choices) {
    specialization.sampler = static_cast<std::uint32_t>(choices.sampler);
    specialization.stableSphereTest = choices.sphereTest == SphereTest::Stable;
    specialization.watertightTriangles = choices.triangleTest == TriangleTest::Watertight;
    specialization.scaledRayOffset = choices.offset == RayOffset::Scaled;
}

// Everything that decides the SPIR-V: the compiler's version, how it is called (bump
// the recipe when shader_compiler.cpp's settings change), the preamble that selects
// the precision, and every embedded source.
std::uint64_t traceSourceKey(Precision precision) {
    const std::string recipe =
        "trace.comp; glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." +
        std::to_string(GLSLANG_VERSION_MINOR) + "." + std::to_string(GLSLANG_VERSION_PATCH) +
        "; vulkan1.2 spv1.5 optimized; v1; preamble: " + precisionPreamble(precision);
    std::uint64_t key = hashBytes(recipe.data(), recipe.size());
    for (const auto& [name, text] : embeddedShaderSources()) {
        key = hashBytes(name.data(), name.size() + 1,
                        key); // with the NUL: "a"+"bc" differs from "ab"+"c"
        key = hashBytes(text.data(), text.size(), key);
    }
    return key;
}

namespace {

// Fills result step by step; the caller destroys what was made if a step throws.
void buildTracePipeline(TracePipeline& result, const Context& context,
                        const std::vector<std::uint32_t>& spirv, VkPipelineCache cache,
                        const TraceSpecialization& specialization) {
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
    using S = TraceSpecialization;
    const VkSpecializationMapEntry specializationEntries[] = {
        {SPEC_USE_HIERARCHY, offsetof(S, useHierarchy), sizeof(VkBool32)},
        {SPEC_HAS_SPHERES, offsetof(S, hasSpheres), sizeof(VkBool32)},
        {SPEC_HAS_TRIANGLES, offsetof(S, hasTriangles), sizeof(VkBool32)},
        {SPEC_SAMPLER, offsetof(S, sampler), sizeof(std::uint32_t)},
        {SPEC_STABLE_SPHERE_TEST, offsetof(S, stableSphereTest), sizeof(VkBool32)},
        {SPEC_WATERTIGHT_TRIANGLES, offsetof(S, watertightTriangles), sizeof(VkBool32)},
        {SPEC_SCALED_RAY_OFFSET, offsetof(S, scaledRayOffset), sizeof(VkBool32)},
        {SPEC_HAS_MIRRORS, offsetof(S, hasMirrors), sizeof(VkBool32)},
        {SPEC_HAS_SPECULAR, offsetof(S, hasSpecular), sizeof(VkBool32)}};
    const VkSpecializationInfo specializationInfo{
        static_cast<std::uint32_t>(std::size(specializationEntries)), specializationEntries,
        sizeof(specialization), &specialization};
    pipelineInfo.stage.pSpecializationInfo = &specializationInfo;
    pipelineInfo.layout = result.layout;
    VkResult created = vkCreateComputePipelines(context.device, cache, 1, &pipelineInfo, nullptr,
                                                &result.pipeline);
    // The module is only needed while the pipeline is created.
    vkDestroyShaderModule(context.device, module, nullptr);
    VK_CHECK(created);
}

} // namespace

TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv,
                                  VkPipelineCache cache, TraceSpecialization specialization) {
    TracePipeline result;
    try {
        buildTracePipeline(result, context, spirv, cache, specialization);
    } catch (...) {
        destroyTracePipeline(context, result);
        throw;
    }
    return result;
}

TracePipeline loadTracePipeline(const Context& context, const std::filesystem::path& cacheDirectory,
                                TraceSpecialization specialization, Precision precision) {
    const std::uint64_t sourceKey = traceSourceKey(precision);
    std::vector<std::uint32_t> spirv;
    if (std::optional<std::vector<std::uint32_t>> cached =
            loadCachedSpirv(cacheDirectory, sourceKey)) {
        spirv = std::move(*cached);
    } else {
        spirv = compileComputeShader("trace.comp", embeddedShaderLoader(),
                                     precisionPreamble(precision));
        storeCachedSpirv(cacheDirectory, sourceKey, spirv);
    }
    // One driver cache per specialization, as each compiles to different code (the
    // struct has no padding: its bytes are its values).
    const std::uint64_t spirvHash = hashBytes(spirv.data(), spirv.size() * sizeof(std::uint32_t));
    PipelineCache cache = openPipelineCache(
        context, cacheDirectory, hashBytes(&specialization, sizeof(specialization), spirvHash));
    TracePipeline pipeline;
    try {
        pipeline = createTracePipeline(context, spirv, cache.cache, specialization);
        savePipelineCache(context, cache);
    } catch (...) {
        destroyTracePipeline(context, pipeline);
        destroyPipelineCache(context, cache);
        throw;
    }
    destroyPipelineCache(context, cache);
    return pipeline;
}

void destroyTracePipeline(const Context& context, TracePipeline& pipeline) {
    if (pipeline.pipeline) vkDestroyPipeline(context.device, pipeline.pipeline, nullptr);
    if (pipeline.layout) vkDestroyPipelineLayout(context.device, pipeline.layout, nullptr);
    if (pipeline.setLayout)
        vkDestroyDescriptorSetLayout(context.device, pipeline.setLayout, nullptr);
    pipeline = TracePipeline{};
}
