// Scenes larger than one binding's range or one allocation: an array beyond
// maxStorageBufferRange is read through its texel view alone, and the arrays are spread over
// as many buffers as maxMemoryAllocationSize takes. The hidden --max-storage-range and
// --max-allocation lower those limits, so that a small scene takes the path of a large one:
// its image must be the same bytes as under the real limits.
#include "gpu/context.h"
#include "packing/scene_packing.h"
#include "render/scene_upload.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

// A mesh of 200 triangles and a few spheres: every array but the textures' has elements.
std::string meshAndSpheres() {
    std::string text = "amb: 0.1 0.1 0.1\nlight\npos: 2 3 1\ncol: 1 1 1\n";
    int objects = 1;
    for (int i = 0; i < 4; ++i, ++objects)
        text += "sphere\npos: " + std::to_string(-1.5 + i) +
                " 0.8 -5\nrad: 0.3\ndif: 0.6 0.3 0.2\nspe: 0.3 0.3 0.3\nshi: 20\n";
    for (int i = 0; i < 200; ++i, ++objects) {
        const double x = -2.0 + 0.02 * i;
        text += "triangle\n";
        for (const std::string& corner :
             {std::to_string(x) + " -1 -4.5\n", std::to_string(x + 0.05) + " -1 -4.5\n",
              std::to_string(x) + " -0.2 -4\n"})
            text += "pos: " + corner + "nor: 0 0.5 1\ndif: 0.2 0.5 0.3\nspe: 0.2 0.2 0.2\nshi: 5\n";
    }
    return std::to_string(objects) + "\n" + text;
}

TEST(SceneLimits, ArraysBeyondOneBindingOrAllocationRenderTheSameImage) {
    const std::filesystem::path dir = freshOutputDir("scene-limits/same-image");
    const std::filesystem::path scene = dir / "mesh.scene";
    writeTextFile(scene, meshAndSpheres());
    for (const std::string accel : {"bvh", "none"}) {
        const std::vector<std::string> common = {scene.string(), "--width", "64",  "--height",
                                                 "48",           "--accel", accel, "--validate"};
        std::vector<std::string> whole = common, split = common;
        whole.insert(whole.end(), {"-o", (dir / (accel + "-whole.png")).string()});
        // 256 bytes: the corners and the normals (9,600 bytes each), the nodes and the
        // materials are beyond it; 16,384: the arrays take several buffers.
        split.insert(split.end(), {"-o", (dir / (accel + "-split.png")).string(),
                                   "--max-storage-range", "256", "--max-allocation", "16384"});
        for (const auto& args : {whole, split}) {
            const ProcessResult run = runRaytracer(args);
            ASSERT_EQ(run.exitCode, 0) << run.err;
        }
        const std::string expected = readWholeFile(dir / (accel + "-whole.png"));
        EXPECT_FALSE(expected.empty());
        EXPECT_EQ(readWholeFile(dir / (accel + "-split.png")), expected) << accel;
    }
}

TEST(SceneLimits, WhatCannotBeReadSoNamesTheLimitAndTheDevice) {
    const std::filesystem::path dir = freshOutputDir("scene-limits/errors");
    const std::filesystem::path scene = dir / "mesh.scene";
    writeTextFile(scene, meshAndSpheres());
    const std::vector<std::string> common = {
        scene.string(), "-o", (dir / "x.png").string(), "--width", "16", "--height", "16"};
    struct Case {
        std::vector<std::string> more;
        std::string expected;
    };
    const Case cases[] = {
        // The storage path reads every array from its binding.
        {{"--max-storage-range", "256", "--storage-reads"},
         "error: the scene's triangle corners take 9600 bytes, more than this device's "
         "maxStorageBufferRange of 256 bytes (llvmpipe"},
        // fp64 reads its doubles from storage.
        {{"--max-storage-range", "256", "--precision", "fp64"},
         "error: the scene's triangle corners take 19200 bytes, more than this device's "
         "maxStorageBufferRange of 256 bytes"},
        // One array in one allocation.
        {{"--max-allocation", "4096"},
         "error: the scene's triangle corners take 9600 bytes, more than this device's "
         "maxMemoryAllocationSize of 4096 bytes (llvmpipe"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = common;
        args.insert(args.end(), c.more.begin(), c.more.end());
        const ProcessResult run = runRaytracer(args);
        EXPECT_NE(run.exitCode, 0);
        EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.err;
    }
}

// The upload itself: how many buffers, and which bindings see only the zeroed slot.
TEST(SceneLimits, TheUploadSpreadsTheArraysAndViewsTheLargeOnes) {
    Context context;
    createInstance(context, {}, true);
    createDevice(context, "");
    Scene scene;
    for (int i = 0; i < 100; ++i) {
        Triangle triangle{};
        for (int k = 0; k < 3; ++k)
            triangle.vertices[k].position = glm::dvec3(i + (k == 1), k == 2, -2);
        scene.triangles.push_back(triangle);
    }
    const PackedScene packed = packSceneInFileOrder(scene);
    GpuScene whole = uploadScene(context, packed);
    EXPECT_EQ(whole.buffers.size(), 1u);
    EXPECT_EQ(whole.ranges[BINDING_TRIANGLE_CORNERS].range, 4800u);
    destroyGpuScene(context, whole);

    context.properties.limits.maxStorageBufferRange = 1024;
    context.maxMemoryAllocationSize = 5000;
    GpuScene split = uploadScene(context, packed);
    EXPECT_TRUE(split.texelReads);
    EXPECT_GE(split.buffers.size(), 2u);
    EXPECT_EQ(split.ranges[BINDING_TRIANGLE_CORNERS].range, 16u); // read through its view
    EXPECT_EQ(split.ranges[BINDING_TRIANGLE_CORNERS].offset, 0u);
    EXPECT_EQ(split.ranges[BINDING_TRIANGLE_LAST_VERTICES].range, 400u); // within the range
    destroyGpuScene(context, split);
    EXPECT_THROW(uploadScene(context, packed, false), std::runtime_error);
    destroyContext(context);
}

} // namespace
