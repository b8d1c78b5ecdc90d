// The kernel reads the scene through texel buffers, or through the storage buffers when an
// array exceeds maxTexelBufferElements (or --storage-reads, hidden, which makes that path
// reachable on any device): both paths give the same bytes, in fp32 and in fp64 (whose
// doubles are always read from storage).
#include "gpu/context.h"
#include "render/headless.h"
#include "render/renderer.h"
#include "render/scene_upload.h"
#include "scene/scene_loader.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace {

// Spheres and triangles in one scene, so that leaves of both kinds are read.
std::string mixedScene() {
    std::string text = "amb: 0.1 0.1 0.1\nlight\npos: 2 3 1\ncol: 1 1 1\n";
    for (int i = 0; i < 6; ++i) {
        const std::string x = std::to_string(-2.5 + i);
        text += "sphere\npos: " + x +
                " 0.2 -4\nrad: 0.4\ndif: 0.6 0.3 0.2\nspe: 0.3 0.3 0.3\n"
                "shi: 20\n";
        text += "triangle\n";
        for (const char* corner : {" -1 -5\n", " -1 -3\n", " 0 -4\n"}) {
            const std::string cx = std::to_string(-2.5 + i + (corner[1] == '0' ? 0.4 : 0.0));
            text +=
                "pos: " + cx + corner + "nor: 0 1 0\ndif: 0.2 0.5 0.3\nspe: 0.2 0.2 0.2\nshi: 5\n";
        }
    }
    return std::to_string(1 + 6 * 2) + "\n" + text;
}

std::string runBench(const std::vector<std::string>& args) {
    ProcessResult run = runRaytracer(args);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return benchJson(run);
}

TEST(TexelReads, StorageReadsGiveTheSameBytes) {
    std::filesystem::path dir = freshOutputDir("texel-reads/same-bytes");
    const std::filesystem::path scene = dir / "mixed.scene";
    writeTextFile(scene, mixedScene());
    for (const std::string precision : {"fp32", "fp64"}) {
        for (const std::string accel : {"bvh", "none"}) {
            std::string bytes[2];
            for (int storage = 0; storage < 2; ++storage) {
                const std::filesystem::path png =
                    dir / (precision + accel + std::to_string(storage) + ".png");
                std::vector<std::string> args = {
                    scene.string(), "-o",  png.string(),  "--width", "48",        "--height", "36",
                    "--accel",      accel, "--precision", precision, "--validate"};
                if (storage) args.push_back("--storage-reads");
                ProcessResult run = runRaytracer(args);
                ASSERT_EQ(run.exitCode, 0) << run.err;
                bytes[storage] = readWholeFile(png);
            }
            EXPECT_FALSE(bytes[0].empty());
            EXPECT_EQ(bytes[0], bytes[1])
                << precision << " " << accel << ": the storage-buffer reads changed the image";
        }
    }
}

TEST(TexelReads, BenchSaysWhichPathRan) {
    std::filesystem::path dir = freshOutputDir("texel-reads/bench");
    const std::filesystem::path scene = dir / "mixed.scene";
    writeTextFile(scene, mixedScene());
    const std::vector<std::string> bench = {scene.string(), "--bench",  "1",  "--width",
                                            "16",           "--height", "16", "--validate"};
    EXPECT_NE(runBench(bench).find("\"texel_reads\": true"), std::string::npos);
    std::vector<std::string> storage = bench;
    storage.push_back("--storage-reads");
    EXPECT_NE(runBench(storage).find("\"texel_reads\": false"), std::string::npos);
    // fp64 reads all but its doubles through texel buffers.
    std::vector<std::string> fp64 = bench;
    fp64.insert(fp64.end(), {"--precision", "fp64"});
    EXPECT_NE(runBench(fp64).find("\"texel_reads\": true"), std::string::npos);
}

// An array beyond maxTexelBufferElements takes the storage path with a note naming it; a
// lowered limit on lavapipe stands in for a device with a small one.
TEST(TexelReads, AnArrayBeyondTheTexelLimitFallsBackWithANote) {
    Context context;
    createInstance(context, {}, true);
    createDevice(context, "");
    Scene scene;
    scene.spheres.resize(100);
    const PackedScene packed = packSceneInFileOrder(scene);
    GpuScene fits = uploadScene(context, packed);
    EXPECT_TRUE(fits.texelReads);
    EXPECT_EQ(fits.storageReadsNote, "");
    destroyGpuScene(context, fits);
    context.properties.limits.maxTexelBufferElements = 99;
    GpuScene beyond = uploadScene(context, packed);
    EXPECT_FALSE(beyond.texelReads);
    EXPECT_NE(beyond.storageReadsNote.find("spheres take 100 texels, more than this device's "
                                           "maxTexelBufferElements of 99"),
              std::string::npos)
        << beyond.storageReadsNote;
    destroyGpuScene(context, beyond);
    destroyContext(context);
}

// The triangles' corners are three texels a triangle: a strip of 40 triangles fits 99 texels
// as 40 last vertices and 81 shared vertices, not as 120 corners.
TEST(TexelReads, TriangleCornersBeyondTheTexelLimitFallBackWithANote) {
    Context context;
    createInstance(context, {}, true);
    createDevice(context, "");
    Scene scene;
    for (int i = 0; i < 40; ++i) {
        Triangle triangle{};
        for (int k = 0; k < 3; ++k)
            triangle.vertices[k].position = glm::dvec3(i + (k == 1), k == 2, -2);
        scene.triangles.push_back(triangle);
    }
    const PackedScene packed = packSceneInFileOrder(scene);
    context.properties.limits.maxTexelBufferElements = 99;
    GpuScene beyond = uploadScene(context, packed);
    EXPECT_FALSE(beyond.texelReads);
    EXPECT_EQ(beyond.storageReadsNote,
              "Storage-buffer reads: the scene's triangle corners take 120 texels, more than "
              "this device's maxTexelBufferElements of 99");
    destroyGpuScene(context, beyond);
    context.properties.limits.maxTexelBufferElements = 120;
    GpuScene fits = uploadScene(context, packed);
    EXPECT_TRUE(fits.texelReads) << fits.storageReadsNote;
    destroyGpuScene(context, fits);
    destroyContext(context);
}

// The kernel compiles beside the upload for texel reads; when the upload falls back to
// storage reads, the renderer compiles it again for them, and renders what
// --storage-reads renders.
TEST(TexelReads, ARendererWhoseUploadFallsBackRendersAsStorageReads) {
    Context context;
    createInstance(context, {}, true);
    createDevice(context, "");
    const Scene scene = parseScene(mixedScene(), "mixed.scene");
    const std::uint32_t messagesBefore = validationMessageCount();
    auto render = [&](bool storageReads, bool expectTexelReads) {
        RenderSettings settings;
        settings.width = 48;
        settings.height = 36;
        settings.storageReads = storageReads;
        Renderer renderer;
        HeadlessTarget target;
        createRenderer(renderer, context, scene, settings);
        EXPECT_EQ(renderer.specialization.texelReads != VK_FALSE, expectTexelReads);
        createHeadlessTarget(target, context, renderer);
        renderHeadlessFrame(target, context, renderer);
        const Image8 image = readHeadlessImage(target, renderer);
        destroyHeadlessTarget(target, context);
        destroyRenderer(renderer, context);
        return image.rgba;
    };
    const std::vector<std::uint8_t> texels = render(false, true);
    const std::vector<std::uint8_t> storage = render(true, false);
    context.properties.limits.maxTexelBufferElements = 10; // the 18 triangle corners exceed it
    const std::vector<std::uint8_t> fallenBack = render(false, false);
    EXPECT_EQ(fallenBack, storage);
    EXPECT_EQ(texels, storage);
    EXPECT_EQ(validationMessageCount(), messagesBefore);
    destroyContext(context);
}

TEST(TexelReads, StorageReadsIsNotInTheUsageText) {
    EXPECT_EQ(runRaytracer({"--help"}).out.find("--storage-reads"), std::string::npos);
}

} // namespace
