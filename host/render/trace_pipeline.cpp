#include "render/trace_pipeline.h"

#include "base/hash.h"
#include "base/scope_guard.h"
#include "gpu/pipeline_cache.h"
#include "gpu/shader_compiler.h"
#include "gpu/spirv_specializer.h"
#include "gpu/vk_check.h"
#include "render/bindings.h"
#include "render/kernel_sources.h"
#include "shared.h"

#include <cstddef>
#include <cstring>
#include <iterator>
#include <map>
#include <optional>
#include <regex>
#include <string>

// Hashed as bytes for the pipeline cache's key: no padding may hide in it.
static_assert(sizeof(TraceSpecialization) == 22 * sizeof(std::uint32_t));

VkDescriptorType bindingDescriptorType(std::uint32_t binding) {
    return kBindings[binding].type;
}

std::string precisionPreamble(Precision precision) {
    return precision == Precision::Fp64 ? "#define RT_FP64 1\n" : "";
}

void applyKernelChoices(TraceSpecialization& specialization, const KernelChoices& choices) {
    specialization.sampler = static_cast<std::uint32_t>(choices.sampler);
    specialization.stableSphereTest = choices.sphereTest == SphereTest::Stable;
    specialization.watertightTriangles = choices.triangleTest == TriangleTest::Watertight;
    specialization.rayOffset = static_cast<std::uint32_t>(choices.offset);
}

// Everything that decides the SPIR-V: the compiler and its settings, the preamble that
// selects the precision, and every embedded source.
std::uint64_t traceSourceKey(Precision precision) {
    const std::string recipe =
        "trace.comp; " + shaderCompilerRecipe() + "; preamble: " + precisionPreamble(precision);
    std::uint64_t key = hashBytes(recipe.data(), recipe.size());
    for (const auto& [name, text] : embeddedShaderSources()) {
        key = hashBytes(name.data(), name.size() + 1,
                        key); // with the NUL: "a"+"bc" differs from "ab"+"c"
        key = hashBytes(text.data(), text.size(), key);
    }
    return key;
}

namespace {

// Where each specialization constant's value lies in TraceSpecialization.
std::vector<VkSpecializationMapEntry> specializationMapEntries() {
    using S = TraceSpecialization;
    return {{SPEC_USE_HIERARCHY, offsetof(S, useHierarchy), sizeof(VkBool32)},
            {SPEC_HAS_SPHERES, offsetof(S, hasSpheres), sizeof(VkBool32)},
            {SPEC_HAS_TRIANGLES, offsetof(S, hasTriangles), sizeof(VkBool32)},
            {SPEC_SAMPLER, offsetof(S, sampler), sizeof(std::uint32_t)},
            {SPEC_STABLE_SPHERE_TEST, offsetof(S, stableSphereTest), sizeof(VkBool32)},
            {SPEC_WATERTIGHT_TRIANGLES, offsetof(S, watertightTriangles), sizeof(VkBool32)},
            {SPEC_RAY_OFFSET, offsetof(S, rayOffset), sizeof(std::uint32_t)},
            {SPEC_HAS_MIRRORS, offsetof(S, hasMirrors), sizeof(VkBool32)},
            {SPEC_HAS_SPECULAR, offsetof(S, hasSpecular), sizeof(VkBool32)},
            {SPEC_HAS_MIRROR_SHARES, offsetof(S, hasMirrorShares), sizeof(VkBool32)},
            {SPEC_SHIFT_SHADOW_ORIGIN, offsetof(S, shiftShadowOrigin), sizeof(VkBool32)},
            {SPEC_HAS_TEXTURES, offsetof(S, hasTextures), sizeof(VkBool32)},
            {SPEC_TEXEL_READS, offsetof(S, texelReads), sizeof(VkBool32)},
            {SPEC_INDEXED_TRIANGLES, offsetof(S, indexedTriangles), sizeof(VkBool32)},
            {SPEC_BAKED_SPHERES, offsetof(S, bakedSpheres), sizeof(VkBool32)},
            {SPEC_BAKED_SPHERE_COUNT, offsetof(S, bakedSphereCount), sizeof(std::uint32_t)},
            {SPEC_BAKED_LIGHT_COUNT, offsetof(S, bakedLightCount), sizeof(std::uint32_t)},
            {SPEC_RECORD_PIXEL, offsetof(S, recordPixel), sizeof(VkBool32)},
            {SPEC_FLOAT_OUTPUT, offsetof(S, floatOutput), sizeof(VkBool32)},
            {SPEC_OUTPUT_PART, offsetof(S, outputPart), sizeof(VkBool32)},
            {SPEC_STACK_DEPTH, offsetof(S, stackDepth), sizeof(std::uint32_t)},
            {SPEC_COUNT_WORK, offsetof(S, countWork), sizeof(VkBool32)}};
}

// The constants' values by id, for specializeSpirv.
std::map<std::uint32_t, std::uint32_t> specializationValues(const TraceSpecialization& values) {
    std::map<std::uint32_t, std::uint32_t> byId;
    for (const VkSpecializationMapEntry& entry : specializationMapEntries()) {
        std::uint32_t value = 0;
        std::memcpy(&value, reinterpret_cast<const std::byte*>(&values) + entry.offset,
                    sizeof(value));
        byId[entry.constantID] = value;
    }
    return byId;
}

// The module specialised for these values (host/gpu/spirv_specializer.h), or as it is when
// SPIRV-Tools cannot: createTracePipeline passes the values as specialization constants
// either way, so both give the same kernel.
std::vector<std::uint32_t> specializedSpirv(const std::vector<std::uint32_t>& spirv,
                                            const TraceSpecialization& specialization) {
    std::optional<std::vector<std::uint32_t>> specialized =
        specializeSpirv(spirv, specializationValues(specialization));
    return specialized ? std::move(*specialized) : spirv;
}

} // namespace

TracePipeline createTracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv,
                                  VkPipelineCache cache, TraceSpecialization specialization) {
    TracePipeline result;
    OnFailure release([&] { destroyTracePipeline(context, result); });
    // Binding 0 is the output image the kernel writes; the others are ranges of the scene
    // buffer, or views of them (see shaders/shared.h for what each holds).
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding = 0; binding < BINDING_COUNT; ++binding)
        bindings.push_back(
            {binding, bindingDescriptorType(binding), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
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
    // The module is only needed while the pipeline is created.
    ScopeExit releaseModule([&] { vkDestroyShaderModule(context.device, module, nullptr); });

    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module;
    pipelineInfo.stage.pName = "main";
    const std::vector<VkSpecializationMapEntry> specializationEntries = specializationMapEntries();
    const VkSpecializationInfo specializationInfo{
        static_cast<std::uint32_t>(specializationEntries.size()), specializationEntries.data(),
        sizeof(specialization), &specialization};
    pipelineInfo.stage.pSpecializationInfo = &specializationInfo;
    pipelineInfo.layout = result.layout;
    VK_CHECK(vkCreateComputePipelines(context.device, cache, 1, &pipelineInfo, nullptr,
                                      &result.pipeline));
    return result;
}

namespace {

// The user's sources change under us, so neither SPIR-V nor the driver's cache is kept.
TracePipeline loadFromDirectory(const Context& context, const std::filesystem::path& directory,
                                const TraceSpecialization& specialization, Precision precision) {
    std::vector<std::uint32_t> spirv;
    try {
        spirv = compileComputeShader("trace.comp", directoryShaderLoader(directory),
                                     precisionPreamble(precision));
    } catch (const ShaderCompileError& error) {
        // glslang names files as included ("ERROR: shade.glsl:12: ..."); with the folder
        // in front, an editor or terminal can jump to the line.
        const std::regex located("(ERROR|WARNING): ([A-Za-z0-9_.-]+):([0-9]+):");
        const std::string log = std::regex_replace(error.what(), located,
                                                   "$1: " + (directory / "").string() + "$2:$3:");
        throw ShaderCompileError("the kernel in " + directory.string() +
                                 " does not compile (--shader-dir):\n" + log);
    }
    return createTracePipeline(context, specializedSpirv(spirv, specialization), VK_NULL_HANDLE,
                               specialization);
}

// The kernel as glslang compiles the embedded sources, through the cache under sourceKey.
std::vector<std::uint32_t> compiledEmbeddedSpirv(const std::filesystem::path& cacheDirectory,
                                                 std::uint64_t sourceKey, Precision precision) {
    if (std::optional<std::vector<std::uint32_t>> cached =
            loadCachedSpirv(cacheDirectory, sourceKey))
        return std::move(*cached);
    std::vector<std::uint32_t> spirv =
        compileComputeShader("trace.comp", embeddedShaderLoader(), precisionPreamble(precision));
    storeCachedSpirv(cacheDirectory, sourceKey, spirv);
    return spirv;
}

TracePipeline loadEmbedded(const Context& context, const std::filesystem::path& cacheDirectory,
                           const TraceSpecialization& specialization, Precision precision) {
    // One specialised module and one driver cache per specialization, as each compiles to
    // different code (the struct has no padding: its bytes are its values). sourceKey
    // already names the compiled SPIR-V, so a warm start reads the specialised file alone.
    const std::uint64_t sourceKey = traceSourceKey(precision);
    const std::uint64_t specializedKey =
        hashBytes(&specialization, sizeof(specialization), sourceKey);
    std::vector<std::uint32_t> specialized;
    if (std::optional<std::vector<std::uint32_t>> cached =
            loadCachedSpirv(cacheDirectory, specializedKey, SpirvStage::Specialized)) {
        specialized = std::move(*cached);
    } else {
        specialized = specializedSpirv(compiledEmbeddedSpirv(cacheDirectory, sourceKey, precision),
                                       specialization);
        storeCachedSpirv(cacheDirectory, specializedKey, specialized, SpirvStage::Specialized);
    }
    PipelineCache cache = openPipelineCache(context, cacheDirectory, specializedKey);
    ScopeExit releaseCache([&] { destroyPipelineCache(context, cache); });
    TracePipeline pipeline = createTracePipeline(context, specialized, cache.cache, specialization);
    OnFailure release([&] { destroyTracePipeline(context, pipeline); });
    savePipelineCache(context, cache);
    return pipeline;
}

} // namespace

TracePipeline loadTracePipeline(const Context& context, const KernelSource& source,
                                TraceSpecialization specialization, Precision precision) {
    if (!source.shaderDirectory.empty())
        return loadFromDirectory(context, source.shaderDirectory, specialization, precision);
    return loadEmbedded(context, source.cacheDirectory, specialization, precision);
}

void destroyTracePipeline(const Context& context, TracePipeline& pipeline) {
    if (pipeline.pipeline) vkDestroyPipeline(context.device, pipeline.pipeline, nullptr);
    if (pipeline.layout) vkDestroyPipelineLayout(context.device, pipeline.layout, nullptr);
    if (pipeline.setLayout)
        vkDestroyDescriptorSetLayout(context.device, pipeline.setLayout, nullptr);
    pipeline = TracePipeline{};
}
