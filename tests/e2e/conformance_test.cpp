// Every scene (the project's and the classic assignment's) rendered by the GPU
// program on lavapipe and compared pixel by pixel with the double-precision CPU
// reference, with --depth 0 and --depth 5, once walking the bounding volume hierarchy
// (--accel bvh) and once testing every primitive (--accel none).
//
// Tolerance: at least 99.9% of pixels within 2/255 in every channel, in fp32 and fp64. The
// GPU works in fp32 and the reference in fp64, so colours agree to far below one level
// except where a ray's fate flips between the two precisions: pixels on a silhouette, a
// shadow edge or a reflected edge, where a pixel in ten thousand may take the other side
// (measured: every scene at 99.99% or above, docs/accuracy.md). Each case prints its worst
// figure ("conformance worst"); the failure output keeps both images and a diff image.
//
// fp64 rows (--precision fp64): the same scenes with the geometry in double. The fate of
// a ray then flips only where the float parts (the primary ray's direction, materials,
// lights, colours) decide it, so fp64 must be at least as close as fp32: no more pixels
// outside 2/255 than fp32 on the same scene.
//
// The stress scenes (scenes/stress/) are held to a stricter rule by stability_test: no
// pixel outside the reference's range, at depth 0 and 5.
//
// The two GPU paths must agree exactly: they run the same primitive tests in the same
// primitive order with the same tie rule, and the hierarchy's box test is conservative,
// so a box never hides a hit. Any differing pixel is a traversal bug.
//
// Watertightness: closed meshes on a black background, with rays aimed exactly at
// shared edges and vertices, must show no background pixel where the reference sees
// the mesh (a crack), on either path.
//
// Culling: boxes with a face in a plane through the eye must still be culled (the slab
// test once gave up on every such box), checked by time against the same geometry moved
// off the plane, and the scene matches the reference on both paths.
#include "test_support.h"

#include "model/scene_file.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <utility>

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;
constexpr int kTolerance = 2;
constexpr double kMinimumMatch = 0.999;

struct ConformanceCase {
    std::filesystem::path scene;
    int depth;
};

std::vector<ConformanceCase> allCases() {
    std::vector<ConformanceCase> cases;
    for (const char* folder : {PROJECT_SCENES_DIR, SHARED_SCENES_DIR})
        for (const auto& scene : sceneFilesIn(folder))
            for (int depth : {0, 5})
                cases.push_back({scene, depth});
    return cases;
}

std::string caseName(const testing::TestParamInfo<ConformanceCase>& info) {
    std::string folder = info.param.scene.parent_path().parent_path().filename().string();
    std::string name = folder + "_" + info.param.scene.stem().string() + "_depth" +
                       std::to_string(info.param.depth);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

// Renders scene on the GPU with --accel accel (and any extra flags) into dir; fails the
// test and returns an empty image when the program fails.
Image8 renderGpu(const std::filesystem::path& scene, const std::string& accel,
                 const std::filesystem::path& dir, std::vector<std::string> extra,
                 const std::string& variant = "") {
    std::filesystem::path png = dir / ("gpu-" + accel + variant + ".png");
    std::vector<std::string> args = {scene.string(), "-o",      png.string(),
                                     "--validate",   "--accel", accel};
    args.insert(args.end(), extra.begin(), extra.end());
    ProcessResult run = runRaytracer(args);
    EXPECT_FALSE(run.timedOut);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(hasValidationMessage(run)) << run.err;
    EXPECT_NE(run.err.find(accel == "bvh" ? "Acceleration: BVH" : "Acceleration: none"),
              std::string::npos)
        << run.err;
    if (run.exitCode != 0) return {};
    return readPng(png);
}

long differingPixels(const Image8& a, const Image8& b) {
    long count = 0;
    for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4)
        count += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] ||
                 a.rgba[i + 2] != b.rgba[i + 2];
    return count;
}

// Compares with the reference under the conformance tolerance, keeping images on failure.
ImageComparison expectMatchesReference(const Image8& gpu, const Image8& reference,
                                       const std::filesystem::path& dir, const std::string& label) {
    ImageComparison comparison = compareImages(gpu, reference, kTolerance);
    std::printf("conformance %s: %s\n", label.c_str(), describe(comparison).c_str());
    if (comparison.fractionWithinTolerance < kMinimumMatch) {
        writePng(dir / "reference.png", reference);
        writePng(dir / (label + "-diff.png"), diffImage(gpu, reference, kTolerance));
        ADD_FAILURE() << label << ": " << describe(comparison) << "; images kept in " << dir;
    }
    return comparison;
}

class Conformance : public testing::TestWithParam<ConformanceCase> {};

TEST_P(Conformance, GpuMatchesCpuReferenceWithAndWithoutHierarchy) {
    const ConformanceCase& test = GetParam();
    std::filesystem::path dir = freshOutputDir("conformance/" + caseName({test, 0}));
    std::vector<std::string> size = {"--width",  std::to_string(kWidth),
                                     "--height", std::to_string(kHeight),
                                     "--depth",  std::to_string(test.depth)};
    Image8 bvh = renderGpu(test.scene, "bvh", dir, size);
    Image8 none = renderGpu(test.scene, "none", dir, size);
    std::vector<std::string> fp64 = size;
    fp64.insert(fp64.end(), {"--precision", "fp64"});
    Image8 bvh64 = renderGpu(test.scene, "bvh", dir, fp64, "-fp64");
    Image8 none64 = renderGpu(test.scene, "none", dir, fp64, "-fp64");
    if (HasFailure()) return;

    ReferenceSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.depth = test.depth;
    Image8 reference = renderReference(loadScene(test.scene), settings);
    std::string label = test.scene.filename().string() + " depth " + std::to_string(test.depth);
    ImageComparison fp32 = expectMatchesReference(bvh, reference, dir, label + " bvh");
    ImageComparison fp32none = expectMatchesReference(none, reference, dir, label + " none");
    EXPECT_EQ(differingPixels(bvh, none), 0)
        << "the hierarchy changed pixels; images kept in " << dir;
    ImageComparison double64 = expectMatchesReference(bvh64, reference, dir, label + " bvh fp64");
    ImageComparison double64none =
        expectMatchesReference(none64, reference, dir, label + " none fp64");
    // The worst of each precision, as docs/accuracy.md lists them.
    std::printf(
        "conformance worst %s: fp32 %.3f%%, fp64 %.3f%% within 2/255, max diff %d/255\n",
        label.c_str(),
        100.0 * std::min(fp32.fractionWithinTolerance, fp32none.fractionWithinTolerance),
        100.0 * std::min(double64.fractionWithinTolerance, double64none.fractionWithinTolerance),
        std::max({fp32.maxChannelDifference, fp32none.maxChannelDifference,
                  double64.maxChannelDifference, double64none.maxChannelDifference}));
    EXPECT_EQ(differingPixels(bvh64, none64), 0)
        << "the hierarchy changed pixels in fp64; images kept in " << dir;
    EXPECT_LE(double64.pixels - double64.pixelsWithinTolerance,
              fp32.pixels - fp32.pixelsWithinTolerance)
        << "fp64 is further from the reference than fp32; images kept in " << dir;
    if (!HasFailure()) std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenes, Conformance, testing::ValuesIn(allCases()), caseName);

// ---- Watertightness ----

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

// A scene of closed triangle meshes: each vertex written from one double, so the
// triangles that share it read exactly the same float. Grey, matte, lit by one light at
// the eye (so no shadow edge is in view), with an ambient term, so that every hit is at
// least 0.2 (51/255) in every channel and only a miss is black.
struct MeshSceneWriter {
    std::ostringstream objects;
    int count = 0;
    void triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
        glm::dvec3 n = glm::cross(b - a, c - a);
        objects << "triangle\n";
        for (glm::dvec3 p : {a, b, c})
            objects << "pos: " << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z)
                    << "\nnor: " << number(n.x) << ' ' << number(n.y) << ' ' << number(n.z)
                    << "\ndif: 0.6 0.6 0.6\nspe: 0 0 0\nshi: 1\n";
        ++count;
    }
    std::string text() const {
        return std::to_string(count + 1) +
               "\namb: 0.2 0.2 0.2\nlight\npos: 0 0 0\ncol: 0.7 0.7 0.7\n" + objects.str();
    }
};

// An axis-aligned box, each face cut into 2 x 2 quads (two triangles each), so that the
// planes x = centre.x and y = centre.y hold shared edges, and the face centres shared vertices.
void addSubdividedBox(MeshSceneWriter& scene, glm::dvec3 lo, glm::dvec3 hi) {
    glm::dvec3 mid = 0.5 * (lo + hi);
    for (int axis = 0; axis < 3; ++axis) {
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (double side : {lo[axis], hi[axis]}) {
            double us[3] = {lo[u], mid[u], hi[u]}, vs[3] = {lo[v], mid[v], hi[v]};
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) {
                    auto corner = [&](int a, int b) {
                        glm::dvec3 p;
                        p[axis] = side;
                        p[u] = us[a];
                        p[v] = vs[b];
                        return p;
                    };
                    scene.triangle(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1));
                    scene.triangle(corner(i, j), corner(i + 1, j + 1), corner(i, j + 1));
                }
        }
    }
}

// A UV sphere of rings x segments quads (fans at the poles), vertices computed once.
void addTessellatedSphere(MeshSceneWriter& scene, glm::dvec3 centre, double radius, int rings,
                          int segments) {
    auto at = [&](int ring, int segment) {
        double theta = M_PI * ring / rings, phi = 2 * M_PI * (segment % segments) / segments;
        if (ring == 0) return centre + glm::dvec3(0, radius, 0);
        if (ring == rings) return centre - glm::dvec3(0, radius, 0);
        return centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                            std::sin(theta) * std::sin(phi));
    };
    for (int ring = 0; ring < rings; ++ring)
        for (int segment = 0; segment < segments; ++segment) {
            glm::dvec3 a = at(ring, segment), b = at(ring, segment + 1),
                       c = at(ring + 1, segment + 1), d = at(ring + 1, segment);
            if (ring != 0) scene.triangle(a, b, c);
            if (ring != rings - 1) scene.triangle(a, c, d);
        }
}

bool isBackground(const Image8& image, int x, int y) {
    const std::uint8_t* p = &image.rgba[4 * (std::size_t(y) * image.width + x)];
    return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

// Pixels the reference sees the mesh in (with all 8 neighbours, when interiorOnly, so that
// a silhouette pixel whose fate fp32 and fp64 may disagree on is not counted) that the GPU
// shows as background.
long cracks(const Image8& gpu, const Image8& reference, bool interiorOnly) {
    long count = 0;
    for (int y = 1; y + 1 < reference.height; ++y)
        for (int x = 1; x + 1 < reference.width; ++x) {
            bool covered = !isBackground(reference, x, y);
            for (int dy = -1; interiorOnly && dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    covered = covered && !isBackground(reference, x + dx, y + dy);
            count += covered && isBackground(gpu, x, y);
        }
    return count;
}

void expectWatertight(const std::string& name, const std::string& sceneText, int width, int height,
                      bool interiorOnly) {
    std::filesystem::path dir = freshOutputDir("watertight/" + name);
    std::filesystem::path scenePath = dir / (name + ".scene");
    writeTextFile(scenePath, sceneText);
    std::vector<std::string> flags = {
        "--width", std::to_string(width), "--height", std::to_string(height), "--depth",
        "0",       "--background",        "0,0,0"};
    ReferenceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.depth = 0;
    settings.background = glm::dvec3(0.0);
    Image8 reference = renderReference(loadScene(scenePath), settings);
    long covered = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            covered += !isBackground(reference, x, y);
    ASSERT_GT(covered, width * height / 10) << "the mesh should fill a good part of the image";
    for (const std::string accel : {"bvh", "none"}) {
        Image8 gpu = renderGpu(scenePath, accel, dir, flags);
        if (testing::Test::HasFailure()) return;
        long found = cracks(gpu, reference, interiorOnly);
        std::printf("watertight %s %s: %ld background pixels inside the mesh of %ld\n",
                    name.c_str(), accel.c_str(), found, covered);
        EXPECT_EQ(found, 0) << accel << ": cracks; images kept in " << dir;
        expectMatchesReference(gpu, reference, dir, name + " " + accel);
    }
    if (!testing::Test::HasFailure()) std::filesystem::remove_all(dir);
}

// An odd image size puts the middle column's and row's pixel centres exactly on x = 0 and
// y = 0: those rays have a direction component of exactly 0 and run along the shared edges
// in the planes x = 0 and y = 0 of the box's front face, and through the vertex at its
// centre. The hierarchy's boxes have faces in those same planes (the halves of the box), so
// the slab test meets the origin-in-the-plane case of a zero direction component there.
TEST(Watertight, SubdividedBoxWithRaysAlongItsEdgesAndThroughItsVertices) {
    MeshSceneWriter scene;
    addSubdividedBox(scene, glm::dvec3(-1, -1, -5), glm::dvec3(1, 1, -3));
    expectWatertight("box", scene.text(), 81, 81, false);
}

// The same with the box's left face in the plane x = 0: the middle column's rays graze
// that face edge-on and must still hit the front face's edge.
TEST(Watertight, BoxWithAFaceInTheRaysPlane) {
    MeshSceneWriter scene;
    addSubdividedBox(scene, glm::dvec3(0, -1, -5), glm::dvec3(2, 1, -3));
    expectWatertight("box_face_in_plane", scene.text(), 81, 81, false);
}

// A finely tessellated sphere (about 3000 triangles sharing every edge) seen whole.
TEST(Watertight, TessellatedSphereShowsNoCracks) {
    MeshSceneWriter scene;
    addTessellatedSphere(scene, glm::dvec3(0, 0, -3), 1.2, 40, 80);
    expectWatertight("sphere", scene.text(), 161, 121, true);
}

// ---- Culling ----

// A grid of count flat triangles in the plane y = height (through the eye when height is
// 0, so every box of the hierarchy has its lower and upper y faces in a plane holding the
// primary rays' origin), stretching away from the eye, and a box behind them.
std::string trianglesInAPlane(double height, int count) {
    MeshSceneWriter scene;
    constexpr int kColumns = 50;
    for (int i = 0; i < count; ++i) {
        double x = 0.5 * (i % kColumns - kColumns / 2), z = -1.0 - 0.5 * (i / kColumns);
        scene.triangle({x, height, z}, {x, height, z - 0.25}, {x + 0.25, height, z});
    }
    addSubdividedBox(scene, glm::dvec3(-2, -1.5, -12), glm::dvec3(2, 1.5, -10));
    return scene.text();
}

// The hierarchy's work over one frame at 160x120 (--count-work: interior nodes visited and
// leaf primitives tested, counted by the kernel): the same numbers on any machine at any load.
struct HierarchyWork {
    std::uint64_t nodeVisits = 0, leafPrimitiveTests = 0;
};

HierarchyWork hierarchyWork(const std::filesystem::path& scene) {
    ProcessResult bench = runRaytracer({scene.string(), "--bench", "1", "--width", "160",
                                        "--height", "120", "--accel", "bvh", "--count-work"});
    EXPECT_EQ(bench.exitCode, 0) << bench.err;
    HierarchyWork work;
    for (auto [key, value] : {std::pair{"\"node_visits\": ", &work.nodeVisits},
                              std::pair{"\"leaf_primitive_tests\": ", &work.leafPrimitiveTests}}) {
        const std::size_t at = bench.out.find(key);
        if (at == std::string::npos) {
            ADD_FAILURE() << "no " << key << "in " << bench.out;
            continue;
        }
        *value = std::stoull(bench.out.substr(at + std::strlen(key)));
    }
    return work;
}

// 2000 triangles in the plane y = 0 against the same moved to y = 0.001: the same work
// when boxes are culled, and many times more when the slab test cannot cull a box whose
// face holds the ray's origin (which on lavapipe made the frame 11x slower).
TEST(Culling, GeometryInAPlaneThroughTheEyeCostsNoMoreThanOffIt) {
    std::filesystem::path dir = freshOutputDir("culling/work");
    std::filesystem::path onPlane = dir / "on-plane.scene", offPlane = dir / "off-plane.scene";
    writeTextFile(onPlane, trianglesInAPlane(0.0, 2000));
    writeTextFile(offPlane, trianglesInAPlane(0.001, 2000));
    const HierarchyWork on = hierarchyWork(onPlane), off = hierarchyWork(offPlane);
    if (testing::Test::HasFailure()) return;
    std::printf("culling: %llu nodes visited and %llu triangles tested in the plane through "
                "the eye, %llu and %llu off it\n",
                static_cast<unsigned long long>(on.nodeVisits),
                static_cast<unsigned long long>(on.leafPrimitiveTests),
                static_cast<unsigned long long>(off.nodeVisits),
                static_cast<unsigned long long>(off.leafPrimitiveTests));
    EXPECT_GT(off.nodeVisits, 0u) << "the kernel counted nothing";
    EXPECT_LT(on.nodeVisits, 2 * off.nodeVisits)
        << "boxes with a face through the eye are not culled";
    EXPECT_LT(on.leafPrimitiveTests, 2 * off.leafPrimitiveTests)
        << "boxes with a face through the eye are not culled";
}

// Many samples per pixel: lavapipe ends an invocation's loops after 65535 iterations in all
// (docs/design.md), which 256 samples of a pixel looking into mirrors.scene's mirrors pass.
// With --sampler grid the samples are the reference's, so the image must match it as one
// sample does, through the hierarchy and without it; none of its pixels is named wrong.
TEST(ManySamples, AGridOf256SamplesMatchesTheReference) {
    std::filesystem::path dir = freshOutputDir("many-samples/grid");
    const std::filesystem::path scene = std::filesystem::path(PROJECT_SCENES_DIR) / "mirrors.scene";
    constexpr int kSide = 48;
    ReferenceSettings settings;
    settings.width = kSide;
    settings.height = kSide;
    settings.spp = 256;
    const Image8 reference = renderReference(loadScene(scene), settings);
    for (const std::string accel : {"bvh", "none"}) {
        const std::filesystem::path png = dir / ("gpu-" + accel + ".png");
        ProcessResult run =
            runRaytracer({scene.string(), "-o", png.string(), "--validate", "--accel", accel,
                          "--width", std::to_string(kSide), "--height", std::to_string(kSide),
                          "--spp", "256", "--sampler", "grid"});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(run.err.find("may be wrong"), std::string::npos) << run.err;
        expectMatchesReference(readPng(png), reference, dir, "256 grid samples " + accel);
    }
}

// What one sample alone cannot finish within the driver's loop iterations is said: every
// primary ray of --accel none tests 70,000 triangles, one loop iteration each.
TEST(ManySamples, PixelsTheDriverCutsShortAreNamed) {
    std::filesystem::path dir = freshOutputDir("many-samples/cut-short");
    const std::filesystem::path scenePath = dir / "many.scene";
    writeTextFile(scenePath, trianglesInAPlane(-1.0, 70000));
    const std::vector<std::string> common = {scenePath.string(), "--width", "8", "--height", "8"};
    std::vector<std::string> none = common, bvh = common;
    none.insert(none.end(), {"-o", (dir / "none.png").string(), "--accel", "none"});
    bvh.insert(bvh.end(), {"-o", (dir / "bvh.png").string(), "--accel", "bvh"});
    ProcessResult cut = runRaytracer(none);
    ASSERT_EQ(cut.exitCode, 0) << cut.err;
    EXPECT_NE(cut.err.find("pixels may be wrong: the CPU driver ends a shader invocation's loops "
                           "after 65535 iterations"),
              std::string::npos)
        << cut.err;
    ProcessResult whole = runRaytracer(bvh);
    ASSERT_EQ(whole.exitCode, 0) << whole.err;
    EXPECT_EQ(whole.err.find("may be wrong"), std::string::npos) << whole.err;
}

// The same scene (fewer triangles: the brute-force path tests them all) against the
// reference, and both paths alike.
TEST(Culling, GeometryInAPlaneThroughTheEyeMatchesTheReference) {
    std::filesystem::path dir = freshOutputDir("culling/image");
    std::filesystem::path scenePath = dir / "on-plane.scene";
    writeTextFile(scenePath, trianglesInAPlane(0.0, 500));
    std::vector<std::string> flags = {"--width", std::to_string(kWidth), "--height",
                                      std::to_string(kHeight)};
    ReferenceSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    Image8 reference = renderReference(loadScene(scenePath), settings);
    Image8 bvh = renderGpu(scenePath, "bvh", dir, flags);
    Image8 none = renderGpu(scenePath, "none", dir, flags);
    if (testing::Test::HasFailure()) return;
    expectMatchesReference(bvh, reference, dir, "plane-through-eye bvh");
    EXPECT_EQ(differingPixels(bvh, none), 0) << "images kept in " << dir;
}

} // namespace
