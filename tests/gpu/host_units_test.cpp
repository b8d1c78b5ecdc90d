// Host pieces that need no GPU: the runtime shader compiler, the scene packer, the kernel's
// variants (precision, specialization) and their cache keys.
#include "gpu/context.h"
#include "gpu/shader_compiler.h"
#include "gpu/spirv_specializer.h"
#include "packing/scene_packing.h"
#include "packing/triangle_layout.h"
#include "render/kernel_sources.h"
#include "render/renderer.h"
#include "render/trace_pipeline.h"

#include <gtest/gtest.h>

#include <bit>
#include <map>

namespace {

ShaderSourceLoader loaderFor(const std::map<std::string, std::string>& files) {
    return [files](const std::string& name) -> std::optional<std::string> {
        auto it = files.find(name);
        if (it == files.end()) return std::nullopt;
        return it->second;
    };
}

TEST(ShaderCompiler, EmbeddedKernelCompilesToSpirv) {
    std::vector<std::uint32_t> spirv = compileComputeShader("trace.comp", embeddedShaderLoader());
    ASSERT_GT(spirv.size(), 5u);
    EXPECT_EQ(spirv[0], 0x07230203u); // the SPIR-V magic number
}

// The kernel specialised before the driver sees it (gpu/spirv_specializer.h): the variants
// the values switch off are gone, so the module is smaller, and it holds no specialization
// constant any more; a module SPIRV-Tools cannot read gives nothing (the caller then keeps
// the general module).
TEST(SpirvSpecializer, FreezesTheConstantsAndDropsWhatTheySwitchOff) {
    std::vector<std::uint32_t> spirv = compileComputeShader("trace.comp", embeddedShaderLoader());
    // test2.scene's kernel: brute force, spheres baked, robust methods.
    const std::map<std::uint32_t, std::uint32_t> values = {
        {SPEC_USE_HIERARCHY, 0},
        {SPEC_HAS_SPHERES, 1},
        {SPEC_HAS_TRIANGLES, 1},
        {SPEC_SAMPLER, SAMPLER_R2},
        {SPEC_STABLE_SPHERE_TEST, 1},
        {SPEC_WATERTIGHT_TRIANGLES, 1},
        {SPEC_RAY_OFFSET, RAY_OFFSET_ERROR_BOUND},
        {SPEC_HAS_MIRRORS, 1},
        {SPEC_HAS_SPECULAR, 1},
        {SPEC_TEXEL_READS, 1},
        {SPEC_BAKED_SPHERES, 1},
        {SPEC_BAKED_SPHERE_COUNT, 3},
        {SPEC_BAKED_LIGHT_COUNT, 1},
        {SPEC_RECORD_PIXEL, 0},
        {SPEC_FLOAT_OUTPUT, 0}};
    std::optional<std::vector<std::uint32_t>> specialized = specializeSpirv(spirv, values);
    ASSERT_TRUE(specialized.has_value());
    EXPECT_EQ((*specialized)[0], 0x07230203u);
    EXPECT_LT(specialized->size(), spirv.size() * 4 / 5) << "expected a fifth or more removed";
    // No OpDecorate ... SpecId (decoration 1) left: word 0 is (4 << 16) | OpDecorate (71).
    auto countSpecIds = [](const std::vector<std::uint32_t>& module) {
        int count = 0;
        for (std::size_t i = 5; i + 2 < module.size(); i += module[i] >> 16 ? module[i] >> 16 : 1)
            count += module[i] == ((4u << 16) | 71u) && module[i + 2] == 1u;
        return count;
    };
    EXPECT_GT(countSpecIds(spirv), 10);
    EXPECT_EQ(countSpecIds(*specialized), 0);

    std::vector<std::uint32_t> broken = spirv;
    broken.resize(broken.size() / 2);
    EXPECT_FALSE(specializeSpirv(broken, values).has_value());
}

TEST(ShaderCompiler, ErrorsCarryGlslangLogWithFileAndLine) {
    auto load = loaderFor({{"broken.comp", "#version 460\nlayout(local_size_x = 1) in;\n"
                                           "void main() {\n    undeclaredThing = 1;\n}\n"}});
    try {
        compileComputeShader("broken.comp", load);
        FAIL() << "a broken shader compiled";
    } catch (const ShaderCompileError& error) {
        std::string log = error.what();
        EXPECT_NE(log.find("shader compilation failed"), std::string::npos) << log;
        EXPECT_NE(log.find("broken.comp:4:"), std::string::npos) << log;
        EXPECT_NE(log.find("undeclaredThing"), std::string::npos) << log;
    }
}

TEST(ShaderCompiler, ErrorsInIncludedFilesNameThatFile) {
    auto load =
        loaderFor({{"main.comp", "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                                 "#include \"helper.glsl\"\nlayout(local_size_x = 1) in;\n"
                                 "void main() { helper(); }\n"},
                   {"helper.glsl", "void helper() {\n    float x = nope;\n}\n"}});
    try {
        compileComputeShader("main.comp", load);
        FAIL() << "a broken include compiled";
    } catch (const ShaderCompileError& error) {
        EXPECT_NE(std::string(error.what()).find("helper.glsl:2:"), std::string::npos)
            << error.what();
    }
}

TEST(ShaderCompiler, MissingIncludeIsReported) {
    auto load =
        loaderFor({{"main.comp", "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                                 "#include \"absent.glsl\"\nlayout(local_size_x = 1) in;\n"
                                 "void main() {}\n"}});
    EXPECT_THROW(compileComputeShader("main.comp", load), ShaderCompileError);
}

Material material(double red, double shininess = 10) {
    return {glm::dvec3(red, 0.2, 0.3), glm::dvec3(0.5), shininess};
}

Vertex vertex(glm::dvec3 position, Material m) {
    return {position, glm::dvec3(0, 0, 1), m};
}

TEST(ScenePacking, SharesIdenticalMaterialsAndVertices) {
    Scene scene;
    scene.ambient = glm::dvec3(0.1);
    Material red = material(0.9), blue = material(0.1);
    scene.spheres.push_back({glm::dvec3(0, 0, -3), 1.0, red});
    scene.spheres.push_back({glm::dvec3(2, 0, -3), 0.5, red});
    // Two triangles sharing an edge: 6 vertices in the file, 4 distinct.
    Vertex a = vertex({0, 0, -5}, blue), b = vertex({1, 0, -5}, blue), c = vertex({0, 1, -5}, blue),
           d = vertex({1, 1, -5}, red);
    scene.triangles.push_back({{a, b, c}});
    scene.triangles.push_back({{b, d, c}});
    scene.lights.push_back({glm::dvec3(0, 5, 0), glm::dvec3(1)});

    PackedScene packed = packSceneInFileOrder(scene);
    EXPECT_EQ(packed.materials.size(), 2u);
    EXPECT_EQ(packed.spheres.size(), 2u);
    EXPECT_EQ(packed.sphereMaterials, (std::vector<std::uint32_t>{0, 0}));
    EXPECT_EQ(packed.vertexPositions.size(), 4u);
    // The two halves of the square are one flat patch (w).
    EXPECT_EQ(packed.triangles, (std::vector<glm::uvec4>{{0, 1, 2, 0}, {1, 3, 2, 0}}));
    ASSERT_EQ(packed.vertexNormals.size(), 3 * 4u); // three floats per vertex
    std::vector<std::uint32_t> vertexMaterials;
    for (std::size_t v = 0; v < packed.vertexPositions.size(); ++v)
        vertexMaterials.push_back(vertexMaterial(packed, v));
    EXPECT_EQ(vertexMaterials, (std::vector<std::uint32_t>{1, 1, 1, 0}));
    EXPECT_EQ(glm::vec3(packed.vertexPositions[3]), glm::vec3(1, 1, -5));
    EXPECT_EQ(packed.spheres[1], glm::vec4(2, 0, -3, 0.5f));
    EXPECT_EQ(packed.materials[0].diffuseShininess, glm::vec4(0.9f, 0.2f, 0.3f, 10.0f));
    EXPECT_EQ(packed.lights.size(), 1u);
}

// The kernel's triangle arrays (shared.h): each triangle's corners with the very floats of
// its vertices, the flat patch and two vertex indices in the corners' w, the third vertex
// index apart, and per vertex its normal with its material's index.
TEST(ScenePacking, TrianglesGoToTheKernelAsCornersWithTheirVertexIndices) {
    Scene scene;
    Material red = material(0.9), blue = material(0.1);
    Vertex a = vertex({0, 0, -5}, blue), b = vertex({1, 0, -5}, blue), c = vertex({0, 1, -5}, blue),
           d = vertex({1, 1, -5}, red), e = vertex({5, 0.1, -4}, red);
    d.normal = glm::dvec3(0, 0.6, 0.8);
    scene.triangles.push_back({{a, b, c}});
    scene.triangles.push_back({{b, d, c}});
    scene.triangles.push_back({{e, b, d}}); // not in the square's plane: its own patch
    PackedScene packed = packSceneInFileOrder(scene);
    ASSERT_EQ(packed.triangles.size(), 3u);
    const GpuTriangleArrays arrays = gpuTriangleArrays(packed);
    ASSERT_EQ(arrays.corners.size(), 9u);
    EXPECT_TRUE(arrays.corners64.empty());
    for (std::size_t t = 0; t < 3; ++t) {
        const glm::uvec4 triangle = packed.triangles[t];
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(glm::vec3(arrays.corners[3 * t + k]),
                      glm::vec3(packed.vertexPositions[triangle[k]]));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(arrays.corners[3 * t].w), triangle.w);
        EXPECT_EQ(std::bit_cast<std::uint32_t>(arrays.corners[3 * t + 1].w), triangle.x);
        EXPECT_EQ(std::bit_cast<std::uint32_t>(arrays.corners[3 * t + 2].w), triangle.y);
    }
    EXPECT_EQ(arrays.lastVertices, (std::vector<std::uint32_t>{2, 2, 3}));
    EXPECT_NE(packed.triangles[2].w, packed.triangles[0].w);
    ASSERT_EQ(arrays.normalsAndMaterials.size(), packed.vertexPositions.size());
    EXPECT_EQ(glm::vec3(arrays.normalsAndMaterials[3]), glm::vec3(0, 0.6f, 0.8f));
    for (std::size_t v = 0; v < packed.vertexPositions.size(); ++v)
        EXPECT_EQ(std::bit_cast<std::uint32_t>(arrays.normalsAndMaterials[v].w),
                  vertexMaterial(packed, v));

    // fp64: the corners in double, the words as exact integers.
    const GpuTriangleArrays exact = gpuTriangleArrays(packSceneInFileOrder(scene, Precision::Fp64));
    EXPECT_TRUE(exact.corners.empty());
    ASSERT_EQ(exact.corners64.size(), 9u);
    EXPECT_EQ(exact.corners64[7], glm::dvec4(1, 0, -5, 4)); // triangle 2's corner 1, b; e is 4
    EXPECT_EQ(exact.corners64[8], glm::dvec4(1, 1, -5, 1)); // its corner 2, d; b is vertex 1
}

// Auto's choice (packing/triangle_layout.h): corners wherever they fit the device and take
// at most an eighth of its memory; indexed where they do not fit, or take more and indexed
// takes fewer bytes; and as asked.
TEST(TriangleLayout, AutoKeepsCornersUnlessTheyCrowdOrDoNotFitTheDevice) {
    const std::size_t triangles = 1000000;
    PackedScene packed;
    packed.triangles.resize(triangles);
    packed.vertexPositions.resize(triangles / 2); // a closed mesh's share
    const TriangleLayoutBytes bytes = triangleLayoutBytes(packed);
    EXPECT_EQ(bytes.corners, 52u * triangles);
    EXPECT_EQ(bytes.indexed, 16u * triangles + 16u * triangles / 2);
    const std::uint64_t roomy = 8 * bytes.corners, crowded = 8 * bytes.corners - 8;
    EXPECT_FALSE(indexedTriangles(packed, TriangleLayout::Auto, {true, roomy}));
    EXPECT_FALSE(indexedTriangles(packed, TriangleLayout::Auto, {true, 0})); // memory unknown
    EXPECT_TRUE(indexedTriangles(packed, TriangleLayout::Auto, {true, crowded}));
    EXPECT_TRUE(indexedTriangles(packed, TriangleLayout::Auto, {false, roomy}));
    EXPECT_TRUE(indexedTriangles(packed, TriangleLayout::Indexed, {true, roomy}));
    EXPECT_FALSE(indexedTriangles(packed, TriangleLayout::Corners, {false, crowded}));

    packed.vertexPositions.resize(3 * triangles); // each triangle its own three
    EXPECT_GT(triangleLayoutBytes(packed).indexed, triangleLayoutBytes(packed).corners);
    EXPECT_FALSE(indexedTriangles(packed, TriangleLayout::Auto, {true, crowded}));
    EXPECT_TRUE(indexedTriangles(packed, TriangleLayout::Auto, {false, roomy}));

    packed.vertexPositions64.resize(packed.vertexPositions.size()); // fp64: doubles
    EXPECT_EQ(triangleLayoutBytes(packed).corners, 100u * triangles);
}

TEST(ScenePacking, VerticesDifferingOnlyInMaterialStaySeparate) {
    Scene scene;
    Vertex a = vertex({0, 0, -5}, material(0.1)), b = vertex({1, 0, -5}, material(0.1)),
           c = vertex({0, 1, -5}, material(0.1));
    Vertex cOther = c;
    cOther.material.shininess = 20;
    scene.triangles.push_back({{a, b, c}});
    scene.triangles.push_back({{a, b, cOther}});
    PackedScene packed = packSceneInFileOrder(scene);
    EXPECT_EQ(packed.vertexPositions.size(), 4u);
    EXPECT_EQ(packed.materials.size(), 2u);
}

TEST(ScenePacking, AnEmptySceneHoldsNothing) {
    PackedScene packed = packSceneInFileOrder(Scene{});
    EXPECT_TRUE(packed.spheres.empty());
    EXPECT_TRUE(packed.triangles.empty());
    EXPECT_TRUE(packed.vertexPositions.empty());
    EXPECT_TRUE(packed.materials.empty());
    EXPECT_TRUE(packed.lights.empty());
}

// ---- Kernel variants ----

// Whether SPIR-V declares a capability (OpCapability: opcode 17, two words).
bool declaresCapability(const std::vector<std::uint32_t>& spirv, std::uint32_t capability) {
    for (std::size_t i = 5; i < spirv.size();) {
        std::uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xffffu;
        if (opcode == 17 && i + 1 < spirv.size() && spirv[i + 1] == capability) return true;
        if (words == 0) break;
        i += words;
    }
    return false;
}

constexpr std::uint32_t kCapabilityFloat64 = 10;

TEST(KernelVariants, Fp64PreambleCompilesTheKernelInDouble) {
    std::vector<std::uint32_t> fp32 = compileComputeShader("trace.comp", embeddedShaderLoader(),
                                                           precisionPreamble(Precision::Fp32));
    std::vector<std::uint32_t> fp64 = compileComputeShader("trace.comp", embeddedShaderLoader(),
                                                           precisionPreamble(Precision::Fp64));
    EXPECT_FALSE(declaresCapability(fp32, kCapabilityFloat64));
    EXPECT_TRUE(declaresCapability(fp64, kCapabilityFloat64));
}

TEST(KernelVariants, PrecisionsNeverShareACachedKernel) {
    EXPECT_NE(traceSourceKey(Precision::Fp32), traceSourceKey(Precision::Fp64));
    EXPECT_EQ(traceSourceKey(Precision::Fp64), traceSourceKey(Precision::Fp64));
}

TEST(KernelVariants, Fp64OnADeviceWithoutDoublesFailsWithAClearMessage) {
    VkPhysicalDeviceFeatures features{};
    try {
        requireFloat64(features, "Some GPU");
        FAIL() << "a device without shaderFloat64 was accepted";
    } catch (const std::runtime_error& error) {
        std::string message = error.what();
        EXPECT_NE(message.find("--precision fp64 needs the shaderFloat64 feature"),
                  std::string::npos);
        EXPECT_NE(message.find("Some GPU does not have"), std::string::npos) << message;
        EXPECT_NE(message.find("--precision fp32"), std::string::npos) << message;
    }
    features.shaderFloat64 = VK_TRUE;
    EXPECT_NO_THROW(requireFloat64(features, "Some GPU"));
}

Scene sceneWith(std::vector<Material> materials, std::size_t lights) {
    Scene scene;
    for (std::size_t i = 0; i < materials.size(); ++i)
        scene.spheres.push_back({glm::dvec3(double(i), 0, -3), 0.5, materials[i]});
    for (std::size_t i = 0; i < lights; ++i)
        scene.lights.push_back({glm::dvec3(0, 5, 0), glm::dvec3(1)});
    return scene;
}

TEST(KernelVariants, SpecialisedForWhatTheSceneHolds) {
    Material matte{glm::dvec3(0.5), glm::dvec3(0.0), 10},
        shiny{glm::dvec3(0.5), glm::dvec3(0, 0, 0.1), 10};
    RenderSettings settings;
    TraceSpecialization plain =
        traceSpecialization(packSceneInFileOrder(sceneWith({matte, matte}, 3)), settings);
    EXPECT_FALSE(plain.hasMirrors);
    EXPECT_FALSE(plain.hasSpecular);
    EXPECT_TRUE(plain.hasSpheres);
    EXPECT_FALSE(plain.hasTriangles);
    TraceSpecialization mirror =
        traceSpecialization(packSceneInFileOrder(sceneWith({matte, shiny}, 1)), settings);
    EXPECT_TRUE(mirror.hasMirrors);
    EXPECT_TRUE(mirror.hasSpecular);
    EXPECT_FALSE(mirror.hasMirrorShares); // every share 1: kr is ks, no share read
    // A highlight without a mirror (mir: 0) alone: a highlight, and no reflection loop.
    Material glossy = shiny;
    glossy.mirror = 0.0;
    TraceSpecialization highlight =
        traceSpecialization(packSceneInFileOrder(sceneWith({matte, glossy}, 1)), settings);
    EXPECT_TRUE(highlight.hasSpecular);
    EXPECT_FALSE(highlight.hasMirrors);
    // Beside a mirror, the share is read.
    TraceSpecialization both =
        traceSpecialization(packSceneInFileOrder(sceneWith({glossy, shiny}, 1)), settings);
    EXPECT_TRUE(both.hasMirrors && both.hasMirrorShares);
    settings.depth = 0; // no bounces: highlights, but no reflection loop
    TraceSpecialization flat =
        traceSpecialization(packSceneInFileOrder(sceneWith({matte, shiny}, 1)), settings);
    EXPECT_FALSE(flat.hasMirrors);
    EXPECT_TRUE(flat.hasSpecular);
}

TEST(KernelVariants, GeneralKernelIgnoresTheContentButKeepsChoicesAndHierarchy) {
    Material matte{glm::dvec3(0.5), glm::dvec3(0.0), 10};
    RenderSettings settings;
    settings.generalKernel = true;
    settings.depth = 0;
    settings.kernel.sphereTest = SphereTest::Naive;
    PackedScene packed = packSceneInFileOrder(sceneWith({matte}, 1));
    packed.bvhNodes.resize(1); // as if the scene were large enough for the hierarchy
    TraceSpecialization general = traceSpecialization(packed, settings);
    EXPECT_TRUE(general.hasSpheres && general.hasTriangles && general.hasSpecular &&
                general.hasMirrors && general.hasMirrorShares);
    EXPECT_TRUE(general.useHierarchy);
    EXPECT_FALSE(general.stableSphereTest);
    EXPECT_TRUE(general.watertightTriangles);
}

// A small scene's spheres are baked in (shaders/baked_spheres.glsl): up to
// MAX_BAKED_SPHERES of them on the brute-force path, with any number of lights, and never
// for the general kernel.
TEST(KernelVariants, SmallScenesSpheresAreBakedInUpToTheLimit) {
    Material matte{glm::dvec3(0.5), glm::dvec3(0.0), 10};
    RenderSettings settings;
    const std::vector<Material> most(MAX_BAKED_SPHERES, matte);
    TraceSpecialization baked =
        traceSpecialization(packSceneInFileOrder(sceneWith(most, 6)), settings);
    EXPECT_TRUE(baked.bakedSpheres);
    EXPECT_EQ(baked.bakedSphereCount, MAX_BAKED_SPHERES);
    EXPECT_EQ(baked.bakedLightCount, 6u);

    std::vector<Material> oneTooMany = most;
    oneTooMany.push_back(matte); // as --accel none gives it: brute force, too many to bake
    EXPECT_FALSE(
        traceSpecialization(packSceneInFileOrder(sceneWith(oneTooMany, 1)), settings).bakedSpheres);
    PackedScene withHierarchy = packSceneInFileOrder(sceneWith({matte}, 1));
    withHierarchy.bvhNodes.resize(1);
    EXPECT_FALSE(traceSpecialization(withHierarchy, settings).bakedSpheres);
    settings.generalKernel = true;
    EXPECT_FALSE(
        traceSpecialization(packSceneInFileOrder(sceneWith({matte}, 1)), settings).bakedSpheres);
}

// The traversal stack gets one entry per level of the scene's tree (shaders/bvh.glsl): the
// depth packScene reports, at least 1; the largest for the general kernel, which runs any
// scene.
TEST(KernelVariants, TheStackIsAsDeepAsTheTree) {
    Material matte{glm::dvec3(0.5), glm::dvec3(0.0), 10};
    RenderSettings settings;
    const PackedScene many = packScene(sceneWith(std::vector<Material>(40, matte), 1),
                                       Acceleration::Bvh, Precision::Fp32);
    ASSERT_TRUE(many.hierarchy.used);
    ASSERT_GT(many.hierarchy.depth, 1u);
    EXPECT_EQ(traceSpecialization(many, settings).stackDepth, many.hierarchy.depth);
    const PackedScene one = packScene(sceneWith({matte}, 1), Acceleration::Bvh, Precision::Fp32);
    ASSERT_TRUE(one.hierarchy.used);
    EXPECT_EQ(one.hierarchy.depth, 0u) << "a lone leaf under the root";
    EXPECT_EQ(traceSpecialization(one, settings).stackDepth, 1u);
    settings.generalKernel = true;
    EXPECT_EQ(traceSpecialization(many, settings).stackDepth, BVH_STACK_SIZE);
}

TEST(KernelVariants, MethodChoicesBecomeSpecializationConstants) {
    RenderSettings settings;
    TraceSpecialization robust =
        traceSpecialization(packSceneInFileOrder(sceneWith({}, 1)), settings);
    EXPECT_EQ(robust.sampler, SAMPLER_R2);
    EXPECT_TRUE(robust.stableSphereTest && robust.watertightTriangles);
    EXPECT_EQ(robust.rayOffset, RAY_OFFSET_ERROR_BOUND);
    settings.kernel = {
        Sampler::Stratified, 3, Precision::Fp64, SphereTest::Naive, TriangleTest::MollerTrumbore,
        RayOffset::Fixed};
    TraceSpecialization naive =
        traceSpecialization(packSceneInFileOrder(sceneWith({}, 1)), settings);
    EXPECT_EQ(naive.sampler, SAMPLER_STRATIFIED);
    EXPECT_FALSE(naive.stableSphereTest || naive.watertightTriangles);
    EXPECT_EQ(naive.rayOffset, RAY_OFFSET_FIXED);
}

TEST(ScenePacking, Fp64KeepsGeometryInDoubleAndItsBoxesHoldIt) {
    // Two vertices 1e-9 apart at x = 1e5 are one float but two doubles.
    Material m = material(0.5);
    Scene scene;
    scene.spheres.push_back({glm::dvec3(1e5 + 1e-9, 0.1, -3), 0.3, m});
    Vertex a = vertex({1e5, 0, -5}, m), b = vertex({1e5 + 1e-9, 0, -5}, m),
           c = vertex({1e5, 1, -5}, m);
    scene.triangles.push_back({{a, b, c}});
    scene.triangles.push_back({{b, a, c}});

    PackedScene single = packSceneInFileOrder(scene);
    EXPECT_TRUE(single.spheres64.empty());
    EXPECT_TRUE(single.vertexPositions64.empty());
    EXPECT_EQ(single.vertexPositions.size(), 2u) << "a and b are the same float";

    PackedScene exact = packSceneInFileOrder(scene, Precision::Fp64);
    ASSERT_EQ(exact.spheres64.size(), 1u);
    EXPECT_EQ(exact.spheres64[0], glm::dvec4(1e5 + 1e-9, 0.1, -3, 0.3));
    ASSERT_EQ(exact.vertexPositions64.size(), 3u) << "a and b are different doubles";
    EXPECT_EQ(exact.vertexPositions.size(), 3u);
    EXPECT_EQ(glm::dvec3(exact.vertexPositions64[1]), b.position);
    for (std::size_t v = 0; v < 3; ++v)
        EXPECT_EQ(exact.vertexPositions64[v].w, double(vertexMaterial(exact, v)));

    // Every box, rounded outward to float, holds its primitive's double extent.
    PrimitiveBounds bounds = primitiveBounds(exact);
    ASSERT_EQ(bounds.boxes.size(), 3u);
    const glm::dvec4 sphere = exact.spheres64[0];
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(double(bounds.boxes[0].lo[axis]), sphere[axis] - sphere.w);
        EXPECT_GE(double(bounds.boxes[0].hi[axis]), sphere[axis] + sphere.w);
    }
    for (std::size_t t = 0; t < 2; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            glm::dvec3 p(exact.vertexPositions64[exact.triangles[t][int(k)]]);
            const PrimitiveBox& box = bounds.boxes[1 + t];
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_LE(double(box.lo[axis]), p[axis]);
                EXPECT_GE(double(box.hi[axis]), p[axis]);
            }
        }
}

} // namespace
