// Scenes larger than one binding's range or one allocation: an array beyond
// maxStorageBufferRange is read through its texel view alone, and the arrays are spread over
// as many buffers as maxMemoryAllocationSize takes. The hidden --max-storage-range and
// --max-allocation lower those limits, so that a small scene takes the path of a large one:
// its image must be the same bytes as under the real limits. What cannot fit is refused
// as soon as its triangles are counted, naming the limit, the device and the largest scene
// that fits; a scene at that size renders.
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

// A scene beyond a lowered limit is refused by the early check (scene_capacity.h), which
// names the limit, the device and the largest scene that fits in the triangle layouts
// allowed (--triangle-layout; auto's bound is indexed's, the larger).
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
    const std::string holds =
        "error: " + scene.string() + " holds 200 triangles, more than llvmpipe";
    const Case cases[] = {
        // The storage path reads every array from its binding.
        {{"--max-storage-range", "256", "--storage-reads", "--triangle-layout", "corners"},
         "can hold: its maxStorageBufferRange of 256 bytes (48 a triangle) sets the largest "
         "scene at 5 triangles\n"},
        {{"--max-storage-range", "256", "--storage-reads"},
         "can hold: its maxStorageBufferRange of 256 bytes (16 a triangle, indexed) sets the "
         "largest scene at 16 triangles\n"},
        // fp64 reads its doubles from storage.
        {{"--max-storage-range", "256", "--precision", "fp64", "--triangle-layout", "corners"},
         "can hold: its maxStorageBufferRange of 256 bytes (96 a triangle) sets the largest "
         "scene at 2 triangles in fp64\n"},
        // One array in one allocation: 4096 bytes less the zeroed slot, 48 bytes a triangle.
        {{"--max-allocation", "4096", "--triangle-layout", "corners"},
         "can hold: its maxMemoryAllocationSize of 4096 bytes (48 a triangle, in one "
         "allocation) sets the largest scene at 85 triangles\n"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = common;
        args.insert(args.end(), c.more.begin(), c.more.end());
        const ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 1);
        EXPECT_NE(run.err.find(holds), std::string::npos) << run.err;
        EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
    }
}

// An OBJ of n triangles, each its own three positions; a last line with a word for a number when
// `broken`.
std::string stripObj(int n, bool broken) {
    std::string text;
    for (int i = 0; i < n; ++i)
        text += "v " + std::to_string(0.1 * i) + " 0 0\nv " + std::to_string(0.1 * i + 0.1) +
                " 0 0\nv " + std::to_string(0.1 * i) + " 1 0.2\nf -3 -2 -1\n";
    return broken ? text + "v 0 zero 0\n" : text;
}

// The OBJ's count is checked after its survey, before the text is read: a file one triangle
// over the limit is refused for its size even though its last line is wrong, and a file at
// the limit renders as under the real limits.
TEST(SceneLimits, TheEarlyCheckRunsBeforeTheReadAndLetsTheLargestSceneThrough) {
    const std::filesystem::path dir = freshOutputDir("scene-limits/early");
    const int triangles = 30;
    // --storage-reads, corners: 48 bytes a triangle in the largest array.
    const std::string atLimit = std::to_string(48 * triangles);
    const std::string under = std::to_string(48 * triangles - 1);
    writeTextFile(dir / "strip.obj", stripObj(triangles, false));
    writeTextFile(dir / "broken.obj", stripObj(triangles, true));
    auto run = [&](const std::string& model, const std::string& range, const std::string& png) {
        std::vector<std::string> args = {(dir / model).string(),
                                         "--no-ground",
                                         "--storage-reads",
                                         "--triangle-layout",
                                         "corners",
                                         "--width",
                                         "32",
                                         "--height",
                                         "24",
                                         "--validate",
                                         "-o",
                                         (dir / png).string()};
        if (!range.empty()) args.insert(args.end(), {"--max-storage-range", range});
        return runRaytracer(args);
    };
    const ProcessResult refused = run("broken.obj", under, "broken.png");
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find("broken.obj holds 30 triangles, more than llvmpipe"),
              std::string::npos)
        << refused.err;
    EXPECT_NE(refused.err.find("sets the largest scene at 29 triangles"), std::string::npos);
    const ProcessResult read = run("broken.obj", atLimit, "broken.png");
    EXPECT_EQ(read.exitCode, 3);
    EXPECT_NE(read.err.find("broken.obj:121: error:"), std::string::npos) << read.err;

    const ProcessResult limited = run("strip.obj", atLimit, "limited.png");
    ASSERT_EQ(limited.exitCode, 0) << limited.err;
    const ProcessResult unlimited = run("strip.obj", "", "unlimited.png");
    ASSERT_EQ(unlimited.exitCode, 0) << unlimited.err;
    EXPECT_EQ(readWholeFile(dir / "limited.png"), readWholeFile(dir / "unlimited.png"));
    EXPECT_FALSE(readWholeFile(dir / "limited.png").empty());
}

// A batch goes on past a scene too large for the device, and says so.
TEST(SceneLimits, ABatchSkipsASceneTooLargeForTheDevice) {
    const std::filesystem::path dir = freshOutputDir("scene-limits/batch");
    writeTextFile(dir / "large.obj", stripObj(30, false));
    writeTextFile(dir / "small.obj", stripObj(10, false));
    const ProcessResult run = runRaytracer(
        {(dir / "large.obj").string(), (dir / "small.obj").string(), "-o",
         (dir / "{name}.png").string(), "--storage-reads", "--triangle-layout", "corners",
         "--max-storage-range", "960", "--width", "32", "--height", "24", "--validate"});
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_NE(run.err.find("large.obj holds 30 triangles, more than llvmpipe"), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("sets the largest scene at 20 triangles"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "large.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "small.png"));
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
    // What the early check lets through the upload checks again, array by array.
    try {
        uploadScene(context, packed, {.texelReads = false});
        ADD_FAILURE() << "the corners are beyond the storage range";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what())
                      .find("the scene's triangle corners take 4800 bytes, "
                            "more than this device's maxStorageBufferRange "
                            "of 1024 bytes (llvmpipe"),
                  std::string::npos)
            << error.what();
    }
    destroyContext(context);
}

} // namespace
