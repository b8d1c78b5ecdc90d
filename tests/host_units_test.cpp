// Host pieces that need no GPU: the runtime shader compiler and the scene packer.
#include "scene_gpu.h"
#include "shader_compiler.h"

#include <gtest/gtest.h>

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
    auto load = loaderFor({{"main.comp", "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                                         "#include \"helper.glsl\"\nlayout(local_size_x = 1) in;\n"
                                         "void main() { helper(); }\n"},
                           {"helper.glsl", "void helper() {\n    float x = nope;\n}\n"}});
    try {
        compileComputeShader("main.comp", load);
        FAIL() << "a broken include compiled";
    } catch (const ShaderCompileError& error) {
        EXPECT_NE(std::string(error.what()).find("helper.glsl:2:"), std::string::npos) << error.what();
    }
}

TEST(ShaderCompiler, MissingIncludeIsReported) {
    auto load = loaderFor({{"main.comp", "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                                         "#include \"absent.glsl\"\nlayout(local_size_x = 1) in;\n"
                                         "void main() {}\n"}});
    EXPECT_THROW(compileComputeShader("main.comp", load), ShaderCompileError);
}

Material material(double red, double shininess = 10) {
    return {glm::dvec3(red, 0.2, 0.3), glm::dvec3(0.5), shininess};
}

Vertex vertex(glm::dvec3 position, Material m) { return {position, glm::dvec3(0, 0, 1), m}; }

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

    PackedScene packed = packScene(scene);
    EXPECT_EQ(packed.materials.size(), 2u);
    EXPECT_EQ(packed.spheres.size(), 2u);
    EXPECT_EQ(packed.sphereMaterials, (std::vector<std::uint32_t>{0, 0}));
    EXPECT_EQ(packed.vertexPositions.size(), 4u);
    EXPECT_EQ(packed.triangleVertices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
    ASSERT_EQ(packed.vertexNormals.size(), 3 * 4u); // three floats per vertex
    std::vector<std::uint32_t> vertexMaterials;
    for (std::size_t v = 0; v < packed.vertexPositions.size(); ++v) vertexMaterials.push_back(vertexMaterial(packed, v));
    EXPECT_EQ(vertexMaterials, (std::vector<std::uint32_t>{1, 1, 1, 0}));
    EXPECT_EQ(glm::vec3(packed.vertexPositions[3]), glm::vec3(1, 1, -5));
    EXPECT_EQ(packed.spheres[1], glm::vec4(2, 0, -3, 0.5f));
    EXPECT_EQ(packed.materials[0].diffuseShininess, glm::vec4(0.9f, 0.2f, 0.3f, 10.0f));
    EXPECT_EQ(packed.lights.size(), 1u);
}

TEST(ScenePacking, VerticesDifferingOnlyInMaterialStaySeparate) {
    Scene scene;
    Vertex a = vertex({0, 0, -5}, material(0.1)), b = vertex({1, 0, -5}, material(0.1)),
           c = vertex({0, 1, -5}, material(0.1));
    Vertex cOther = c;
    cOther.material.shininess = 20;
    scene.triangles.push_back({{a, b, c}});
    scene.triangles.push_back({{a, b, cOther}});
    PackedScene packed = packScene(scene);
    EXPECT_EQ(packed.vertexPositions.size(), 4u);
    EXPECT_EQ(packed.materials.size(), 2u);
}

TEST(ScenePacking, AnEmptySceneHoldsNothing) {
    PackedScene packed = packScene(Scene{});
    EXPECT_TRUE(packed.spheres.empty());
    EXPECT_TRUE(packed.triangleVertices.empty());
    EXPECT_TRUE(packed.vertexPositions.empty());
    EXPECT_TRUE(packed.materials.empty());
    EXPECT_TRUE(packed.lights.empty());
}

} // namespace
