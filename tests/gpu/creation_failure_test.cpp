// A creation that fails part-way leaves nothing behind. Each checked Vulkan call of a
// creation (buffers, an image, the trace pipeline with and without its caches, a whole
// renderer, a headless target) is made to fail in turn with VK_ERROR_OUT_OF_DEVICE_MEMORY
// (failNthVulkanCheck), on lavapipe with the validation layer on. Each time the
// VulkanError must reach the caller, and destroying the device, which makes the layer
// report every object still alive, must print nothing.
#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/shader_compiler.h"
#include "gpu/vk_check.h"
#include "render/headless.h"
#include "render/kernel_sources.h"
#include "render/renderer.h"
#include "render/trace_pipeline.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <functional>

namespace {

// Fails the 1st, 2nd, ... checked call of createAndDestroy, each time on a fresh device,
// until it gets through; returns how many steps were failed. createAndDestroy destroys
// what it made when creation succeeds.
std::uint32_t failEachStep(const std::function<void(const Context&)>& createAndDestroy) {
    constexpr std::uint32_t kMostSteps = 200; // far more than any creation here takes
    for (std::uint32_t step = 1; step <= kMostSteps; ++step) {
        Context context;
        createInstance(context, {}, true);
        createDevice(context, "");
        const std::uint32_t messagesBefore = validationMessageCount();
        failNthVulkanCheck(step);
        bool failed = false;
        try {
            createAndDestroy(context);
        } catch (const VulkanError& error) {
            failed = true;
            EXPECT_EQ(error.result, VK_ERROR_OUT_OF_DEVICE_MEMORY) << error.what();
        } catch (const std::exception& error) {
            ADD_FAILURE() << "step " << step << " threw something else: " << error.what();
            failed = true;
        }
        failNthVulkanCheck(0);
        destroyContext(context);
        EXPECT_EQ(validationMessageCount(), messagesBefore)
            << "the validation layer saw a leak or misuse after failing step " << step;
        if (!failed) {
            std::printf("%u steps failed in turn, then creation succeeded\n", step - 1);
            return step - 1;
        }
    }
    ADD_FAILURE() << "still failing after " << kMostSteps << " steps";
    return kMostSteps;
}

std::vector<std::uint32_t> traceKernelSpirv() {
    static const std::vector<std::uint32_t> spirv =
        compileComputeShader("trace.comp", embeddedShaderLoader());
    return spirv;
}

// A sphere, a triangle and a light: every scene array is in use.
Scene smallScene() {
    Scene scene;
    const Material material{glm::dvec3(0.5), glm::dvec3(0.2), 10.0};
    scene.spheres.push_back({glm::dvec3(0, 0, -3), 0.5, material});
    Triangle triangle;
    const glm::dvec3 corners[3] = {{-1, -1, -4}, {1, -1, -4}, {0, 1, -4}};
    for (int k = 0; k < 3; ++k)
        triangle.vertices[k] = {corners[k], glm::dvec3(0, 0, 1), material};
    scene.triangles.push_back(triangle);
    scene.lights.push_back({glm::dvec3(0, 5, 0), glm::dvec3(1)});
    return scene;
}

TEST(CreationFailure, HostBufferLeavesNothing) {
    EXPECT_GE(failEachStep([](const Context& context) {
                  Buffer buffer = createHostBuffer(context, 4096, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
                  destroyBuffer(context, buffer);
              }),
              4u); // create, allocate, bind, map
}

TEST(CreationFailure, DeviceBufferLeavesNothing) {
    const std::vector<std::uint8_t> data(4096, 7);
    // lavapipe's memory is the host's: the buffer is filled where it is mapped.
    EXPECT_GE(failEachStep([&](const Context& context) {
                  Buffer buffer = createDeviceBuffer(context, data.data(), data.size(),
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
                  destroyBuffer(context, buffer);
              }),
              4u); // create, allocate, bind, map
    // A discrete GPU's path.
    EXPECT_GE(
        failEachStep([&](const Context& context) {
            Buffer buffer = createFilledDeviceBuffer(
                context, data.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                [&](void* destination) { std::memcpy(destination, data.data(), data.size()); },
                BufferFill::ThroughStaging);
            destroyBuffer(context, buffer);
        }),
        12u); // staging (4), buffer (3), the copy's command buffer (5)
}

TEST(CreationFailure, ImageLeavesNothing) {
    EXPECT_GE(failEachStep([](const Context& context) {
                  Image image = createImage(context, 16, 16, VK_FORMAT_R8G8B8A8_UNORM,
                                            VK_IMAGE_USAGE_STORAGE_BIT);
                  destroyImage(context, image);
              }),
              4u); // create, allocate, bind, view
}

TEST(CreationFailure, TracePipelineLeavesNothing) {
    const std::vector<std::uint32_t> spirv = traceKernelSpirv();
    EXPECT_GE(failEachStep([&](const Context& context) {
                  TracePipeline pipeline = createTracePipeline(context, spirv);
                  destroyTracePipeline(context, pipeline);
              }),
              4u); // set layout, pipeline layout, module, pipeline
}

TEST(CreationFailure, CachedTracePipelineLeavesNothing) {
    const KernelSource source{{}, freshOutputDir("creation_failure_cache")};
    EXPECT_GE(failEachStep([&](const Context& context) {
                  TracePipeline pipeline = loadTracePipeline(context, source);
                  destroyTracePipeline(context, pipeline);
              }),
              7u); // the driver's cache, the pipeline (4), reading its data back (2)
}

TEST(CreationFailure, RendererLeavesNothing) {
    const Scene scene = smallScene();
    RenderSettings settings;
    settings.width = settings.height = 8;
    settings.progressive = true;
    EXPECT_GE(failEachStep([&](const Context& context) {
                  Renderer renderer;
                  createRenderer(renderer, context, scene, settings);
                  destroyRenderer(renderer, context);
              }),
              // the scene's upload (filled where mapped on lavapipe), the pipeline, descriptors,
              // output image, running sum
              32u);
}

TEST(CreationFailure, HeadlessTargetLeavesNothing) {
    // Only the output image's size is read: no renderer needs to exist.
    Renderer renderer;
    renderer.outputImage.width = renderer.outputImage.height = 8;
    EXPECT_GE(failEachStep([&](const Context& context) {
                  HeadlessTarget target;
                  createHeadlessTarget(target, context, renderer);
                  destroyHeadlessTarget(target, context);
              }),
              6u); // the readback buffer (4), the command buffer, the fence
}

} // namespace
