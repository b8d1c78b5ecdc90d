// The two triangle layouts (packing/triangle_layout.h, --triangle-layout): indexed triangles
// hold the very floats (doubles) that corners do, so every image is the same bytes, whatever
// the precision, read path and hierarchy; auto keeps corners for a small scene, --bench
// says which ran, and indexed takes fewer bytes where the triangles share their vertices.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// A wavy grid of quads whose triangles share their vertices (normal and material too), a
// mirror sphere above it, and a sphere inside it: every triangle read, shadow and bounce.
std::string sharedMeshScene() {
    const int columns = 8, rows = 5;
    auto corner = [&](int i, int j) {
        const double x = -2.0 + 4.0 * i / columns, z = -6.0 + 3.0 * j / rows;
        const double y = -1.0 + 0.3 * std::sin(1.7 * x) * std::cos(2.1 * z);
        const double shade = 0.3 + 0.5 * double(i) / columns;
        return "pos: " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) +
               "\nnor: " + std::to_string(0.2 * std::sin(x)) +
               " 1 0.1\ndif: " + std::to_string(shade) + " 0.4 0.3\nspe: 0.2 0.2 0.2\nshi: 10\n";
    };
    std::string text = "amb: 0.1 0.1 0.1\nlight\npos: 2 3 1\ncol: 1 1 1\n"
                       "light\npos: -3 2 -2\ncol: 0.4 0.4 0.5\n"
                       "sphere\npos: 0.5 0.2 -4.5\nrad: 0.5\ndif: 0.1 0.1 0.1\n"
                       "spe: 0.8 0.8 0.8\nshi: 50\n"
                       "sphere\npos: -1 -1 -5\nrad: 0.3\ndif: 0.7 0.2 0.2\nspe: 0 0 0\nshi: 1\n";
    int objects = 4; // the header counts lights too
    for (int i = 0; i < columns; ++i) {
        for (int j = 0; j < rows; ++j) {
            text += "triangle\n" + corner(i, j) + corner(i + 1, j) + corner(i, j + 1);
            text += "triangle\n" + corner(i + 1, j) + corner(i + 1, j + 1) + corner(i, j + 1);
            objects += 2;
        }
    }
    return std::to_string(objects) + "\n" + text;
}

std::string render(const std::vector<std::string>& args, const std::filesystem::path& png) {
    std::vector<std::string> all = args;
    all.insert(all.end(), {"-o", png.string()});
    const ProcessResult run = runRaytracer(all);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return readWholeFile(png);
}

TEST(TriangleLayouts, IndexedGivesTheSameBytesAsCorners) {
    const std::filesystem::path dir = freshOutputDir("triangle-layouts/same-bytes");
    const std::filesystem::path scene = dir / "mesh.scene";
    writeTextFile(scene, sharedMeshScene());
    for (const std::string precision : {"fp32", "fp64"}) {
        for (const std::string accel : {"bvh", "none"}) {
            for (const bool storage : {false, true}) {
                const std::string name = precision + "-" + accel + (storage ? "-storage" : "");
                std::vector<std::string> args = {
                    scene.string(), "--width",  "48",          "--height",  "36", "--accel",
                    accel,          "--depth",  "3",           "--spp",     "2",  "--precision",
                    precision,      "--offset", "error-bound", "--validate"};
                if (storage) args.push_back("--storage-reads");
                std::vector<std::string> corners = args, indexed = args;
                corners.insert(corners.end(), {"--triangle-layout", "corners"});
                indexed.insert(indexed.end(), {"--triangle-layout", "indexed"});
                const std::string expected = render(corners, dir / (name + "-corners.png"));
                EXPECT_FALSE(expected.empty());
                EXPECT_EQ(render(indexed, dir / (name + "-indexed.png")), expected) << name;
            }
        }
    }
}

// An OBJ model: smooth normals made by the loader, the shadow terminator's shifted points
// (which read the vertex normals) and a pixel's story, the same in both layouts.
TEST(TriangleLayouts, AModelAndAPixelStoryAreTheSameInBothLayouts) {
    const std::filesystem::path dir = freshOutputDir("triangle-layouts/model");
    std::string obj;
    const int n = 12;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double u = 6.2831853 * i / n, v = 3.1415926 * j / n;
            obj += "v " + std::to_string(std::sin(v) * std::cos(u)) + " " +
                   std::to_string(std::cos(v)) + " " + std::to_string(std::sin(v) * std::sin(u)) +
                   "\n";
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = 1 + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) +
                   "\nf " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) +
                   "\n";
        }
    writeTextFile(dir / "ball.obj", obj);
    const std::vector<std::string> args = {
        (dir / "ball.obj").string(), "--width", "40", "--height", "30", "--validate"};
    std::vector<std::string> corners = args, indexed = args;
    corners.insert(corners.end(), {"--triangle-layout", "corners"});
    indexed.insert(indexed.end(), {"--triangle-layout", "indexed"});
    const std::string expected = render(corners, dir / "corners.png");
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(render(indexed, dir / "indexed.png"), expected);

    std::string stories[2];
    for (int k = 0; k < 2; ++k) {
        std::vector<std::string> story = k ? indexed : corners;
        story.insert(story.end(), {"--pixel", "20,15"}); // the story on stdout
        const ProcessResult run = runRaytracer(story);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        stories[k] = run.out;
    }
    EXPECT_NE(stories[0].find("triangle"), std::string::npos) << stories[0];
    EXPECT_EQ(stories[1], stories[0]);
}

// --bench names the layout that ran; auto keeps corners for a scene this small, and indexed
// holds the shared mesh in fewer bytes.
TEST(TriangleLayouts, BenchSaysWhichLayoutRanAndItsBytes) {
    const std::filesystem::path dir = freshOutputDir("triangle-layouts/bench");
    const std::filesystem::path scene = dir / "mesh.scene";
    writeTextFile(scene, sharedMeshScene());
    auto bench = [&](const std::string& layout) {
        const ProcessResult run =
            runRaytracer({scene.string(), "--bench", "1", "--width", "16", "--height", "16",
                          "--triangle-layout", layout, "--validate"});
        EXPECT_EQ(run.exitCode, 0) << run.err;
        return benchJson(run);
    };
    auto bytes = [](const std::string& json) {
        const std::size_t at = json.find("\"gpu_bytes\": ");
        return at == std::string::npos ? 0ull : std::stoull(json.substr(at + 13));
    };
    const std::string automatic = bench("auto"), corners = bench("corners"),
                      indexed = bench("indexed");
    EXPECT_NE(automatic.find("\"triangle_layout\": \"corners\""), std::string::npos) << automatic;
    EXPECT_NE(corners.find("\"triangle_layout\": \"corners\""), std::string::npos) << corners;
    EXPECT_NE(indexed.find("\"triangle_layout\": \"indexed\""), std::string::npos) << indexed;
    EXPECT_EQ(bytes(automatic), bytes(corners));
    EXPECT_GT(bytes(indexed), 0u);
    EXPECT_LT(bytes(indexed), bytes(corners));
}

} // namespace
