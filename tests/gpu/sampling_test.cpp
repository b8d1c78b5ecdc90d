// The sample positions of shaders/sampling.glsl (--sampler, --seed), computed by the real
// shader code on lavapipe through a small compute kernel that calls sampleOffset for a list
// of (pixel, s, n) and writes the offsets back. Checked: one sample is the pixel centre;
// every offset lies in [0,1)^2; grid and stratified put one sample in each cell of their
// grid; the grid is exactly the cell centres; the seed moves jittered samples and only
// those; and r2's sample s does not depend on n, which is what lets a progressive display
// converge to the headless --spp N image.
#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/shader_compiler.h"
#include "gpu/vk_check.h"
#include "render/kernel_sources.h"
#include "render/trace_pipeline.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

namespace {

// Calls sampleOffset(query.xy, query.z, query.w) for each query.
const char* kHarnessSource = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared.h"
layout(local_size_x = 64) in;
layout(constant_id = SPEC_SAMPLER) const uint samplerKind = SAMPLER_R2;
layout(push_constant) uniform FrameParamsBlock { GpuFrameParams params; };
layout(set = 0, binding = 0, std430) readonly buffer Queries { uvec4 queries[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Offsets { vec2 offsets[]; };
#include "sampling.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= queries.length()) return;
    offsets[i] = sampleOffset(queries[i].xy, queries[i].z, queries[i].w);
}
)";

struct Query {
    std::uint32_t x, y, s, n;
};

class SampleOffsets : public testing::Test {
  protected:
    static void SetUpTestSuite() {
        createInstance(context_, {}, true);
        createDevice(context_, "");
        ShaderSourceLoader embedded = embeddedShaderLoader();
        spirv_ = compileComputeShader("harness.comp", [embedded](const std::string& name) {
            return name == "harness.comp" ? std::optional<std::string>(kHarnessSource)
                                          : embedded(name);
        });
    }
    static void TearDownTestSuite() {
        destroyContext(context_);
        EXPECT_EQ(validationMessageCount(), 0u);
    }

    // The offsets of the queries with this sampler and seed.
    std::vector<glm::vec2> offsets(Sampler sampler, std::uint32_t seed,
                                   const std::vector<Query>& queries) {
        const VkDeviceSize queryBytes = queries.size() * sizeof(Query);
        const VkDeviceSize offsetBytes = queries.size() * sizeof(glm::vec2);
        Buffer input = createHostBuffer(context_, queryBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        Buffer output = createHostBuffer(context_, offsetBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memcpy(input.mapped, queries.data(), queryBytes);

        VkDescriptorSetLayoutBinding bindings[2] = {
            {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
        VkDescriptorSetLayoutCreateInfo setInfo{
            VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        setInfo.bindingCount = 2;
        setInfo.pBindings = bindings;
        VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
        VK_CHECK(vkCreateDescriptorSetLayout(context_.device, &setInfo, nullptr, &setLayout));
        VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::GpuFrameParams)};
        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &setLayout;
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &range;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        VK_CHECK(vkCreatePipelineLayout(context_.device, &layoutInfo, nullptr, &layout));

        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = spirv_.size() * sizeof(std::uint32_t);
        moduleInfo.pCode = spirv_.data();
        VkShaderModule module = VK_NULL_HANDLE;
        VK_CHECK(vkCreateShaderModule(context_.device, &moduleInfo, nullptr, &module));
        const std::uint32_t samplerValue = static_cast<std::uint32_t>(sampler);
        VkSpecializationMapEntry entry{SPEC_SAMPLER, 0, sizeof(std::uint32_t)};
        VkSpecializationInfo specialization{1, &entry, sizeof samplerValue, &samplerValue};
        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.stage.pSpecializationInfo = &specialization;
        pipelineInfo.layout = layout;
        VkPipeline pipeline = VK_NULL_HANDLE;
        VK_CHECK(vkCreateComputePipelines(context_.device, VK_NULL_HANDLE, 1, &pipelineInfo,
                                          nullptr, &pipeline));
        vkDestroyShaderModule(context_.device, module, nullptr);

        VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = 1;
        poolInfo.poolSizeCount = 1;
        poolInfo.pPoolSizes = &poolSize;
        VkDescriptorPool pool = VK_NULL_HANDLE;
        VK_CHECK(vkCreateDescriptorPool(context_.device, &poolInfo, nullptr, &pool));
        VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        allocateInfo.descriptorPool = pool;
        allocateInfo.descriptorSetCount = 1;
        allocateInfo.pSetLayouts = &setLayout;
        VkDescriptorSet set = VK_NULL_HANDLE;
        VK_CHECK(vkAllocateDescriptorSets(context_.device, &allocateInfo, &set));
        VkDescriptorBufferInfo buffers[2] = {{input.buffer, 0, queryBytes},
                                             {output.buffer, 0, offsetBytes}};
        VkWriteDescriptorSet writes[2] = {};
        for (std::uint32_t i = 0; i < 2; ++i) {
            writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            writes[i].dstSet = set;
            writes[i].dstBinding = i;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[i].pBufferInfo = &buffers[i];
        }
        vkUpdateDescriptorSets(context_.device, 2, writes, 0, nullptr);

        gpu::GpuFrameParams params{};
        params.counts.w = seed;
        runOneTimeCommands(context_, [&](VkCommandBuffer commands) {
            vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
            vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0,
                                    nullptr);
            vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof params,
                               &params);
            vkCmdDispatch(commands, std::uint32_t((queries.size() + 63) / 64), 1, 1);
            VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                 VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0,
                                 nullptr);
        });
        std::vector<glm::vec2> result(queries.size());
        std::memcpy(result.data(), output.mapped, offsetBytes);

        vkDestroyDescriptorPool(context_.device, pool, nullptr);
        vkDestroyPipeline(context_.device, pipeline, nullptr);
        vkDestroyPipelineLayout(context_.device, layout, nullptr);
        vkDestroyDescriptorSetLayout(context_.device, setLayout, nullptr);
        destroyBuffer(context_, input);
        destroyBuffer(context_, output);
        return result;
    }

    // Every sample of n in each of a few pixels.
    static std::vector<Query> allSamples(std::uint32_t n) {
        std::vector<Query> queries;
        for (std::uint32_t pixel : {0u, 1u, 77u, 4095u})
            for (std::uint32_t s = 0; s < n; ++s)
                queries.push_back({pixel, pixel / 3, s, n});
        return queries;
    }

    static inline Context context_;
    static inline std::vector<std::uint32_t> spirv_;
};

const std::vector<Sampler> kSamplers = {Sampler::Grid, Sampler::Stratified, Sampler::R2};

TEST_F(SampleOffsets, OneSampleIsThePixelCentre) {
    for (Sampler sampler : kSamplers)
        for (const glm::vec2& offset : offsets(sampler, 3, allSamples(1)))
            EXPECT_EQ(offset, glm::vec2(0.5f)) << choiceName(samplerNames(), sampler);
}

TEST_F(SampleOffsets, EveryOffsetLiesInsideThePixel) {
    for (Sampler sampler : kSamplers)
        for (std::uint32_t n : {2u, 7u, 16u, 64u})
            for (const glm::vec2& offset : offsets(sampler, 1, allSamples(n))) {
                EXPECT_GE(offset.x, 0.0f);
                EXPECT_LT(offset.x, 1.0f);
                EXPECT_GE(offset.y, 0.0f);
                EXPECT_LT(offset.y, 1.0f);
            }
}

TEST_F(SampleOffsets, GridAndStratifiedPutOneSampleInEachCell) {
    for (Sampler sampler : {Sampler::Grid, Sampler::Stratified}) {
        for (auto [n, columns, rows] :
             {std::tuple{16u, 4u, 4u}, std::tuple{12u, 4u, 3u}, std::tuple{7u, 7u, 1u}}) {
            std::vector<Query> queries = allSamples(n);
            std::vector<glm::vec2> result = offsets(sampler, 0, queries);
            for (std::size_t first = 0; first < queries.size(); first += n) {
                std::set<std::pair<int, int>> cells;
                for (std::size_t i = first; i < first + n; ++i)
                    cells.insert(
                        {int(result[i].x * float(columns)), int(result[i].y * float(rows))});
                EXPECT_EQ(cells.size(), n) << choiceName(samplerNames(), sampler) << " n " << n;
            }
            if (sampler == Sampler::Grid)
                for (std::size_t i = 0; i < queries.size(); ++i) {
                    std::uint32_t s = queries[i].s;
                    EXPECT_NEAR(result[i].x, (float(s % columns) + 0.5f) / float(columns), 1e-6f);
                    EXPECT_NEAR(result[i].y, (float(s / columns) + 0.5f) / float(rows), 1e-6f);
                }
        }
    }
}

TEST_F(SampleOffsets, TheSeedMovesJitteredSamplesOnly) {
    std::vector<Query> queries = allSamples(16);
    EXPECT_EQ(offsets(Sampler::Grid, 0, queries), offsets(Sampler::Grid, 99, queries));
    for (Sampler sampler : {Sampler::Stratified, Sampler::R2}) {
        std::vector<glm::vec2> a = offsets(sampler, 0, queries), b = offsets(sampler, 99, queries);
        std::size_t moved = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
            moved += a[i] != b[i];
        EXPECT_EQ(moved, a.size()) << choiceName(samplerNames(), sampler);
        EXPECT_EQ(offsets(sampler, 99, queries), b) << "the same seed gives the same samples";
    }
}

TEST_F(SampleOffsets, R2SampleDoesNotDependOnTheSampleCount) {
    // Sample s of a 4-sample pixel is sample s of the same pixel at 16 and at 1000 samples.
    std::vector<Query> queries;
    for (std::uint32_t n : {4u, 16u, 1000u})
        for (std::uint32_t s = 0; s < 4; ++s)
            queries.push_back({5, 9, s, n});
    std::vector<glm::vec2> result = offsets(Sampler::R2, 7, queries);
    for (std::size_t i = 4; i < result.size(); ++i)
        EXPECT_EQ(result[i], result[i % 4]) << i;
    // And r2's first samples spread out: no two of the first 16 closer than a fifth of
    // the 4 x 4 grid's spacing (toroidal distance, as the rotation wraps).
    std::vector<Query> sixteen;
    for (std::uint32_t s = 0; s < 16; ++s)
        sixteen.push_back({5, 9, s, 16});
    std::vector<glm::vec2> points = offsets(Sampler::R2, 7, sixteen);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            glm::vec2 d = glm::abs(points[i] - points[j]);
            d = glm::min(d, glm::vec2(1.0f) - d);
            EXPECT_GT(glm::length(d), 0.25f / 5.0f) << i << " and " << j;
        }
}

} // namespace
