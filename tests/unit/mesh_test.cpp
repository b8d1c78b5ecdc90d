// Models as indexed meshes (host/scene/mesh.h): an OBJ's corners become shared vertices, its
// floor a mesh of its own, every triangle reads back in the scene format's per-vertex form
// (scene_triangles.h), and the packer makes exactly the same GPU arrays from a mesh as from
// the same triangles written per vertex, so a model renders the same bytes either way.
#include "model/model_scene.h"
#include "model/obj_reader.h"
#include "packing/scene_packing.h"
#include "scene/scene_triangles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

Scene modelScene(const std::string& obj, const std::string& mtl = "", bool ground = true) {
    const SourceModel model = parseObj(obj, "model.obj", [&](const std::string& name) {
        return MtlFile{name, mtl};
    });
    ModelSceneSetup setup;
    setup.ground = ground;
    return sceneFromModel(model, setup, "model.obj");
}

// The same scene with every mesh triangle written out per vertex, as a scene file holds it.
Scene perVertexCopy(const Scene& scene) {
    Scene copy = scene;
    copy.meshes.clear();
    copy.triangles.clear();
    forEachTriangle(scene, [&](const Triangle& triangle) { copy.triangles.push_back(triangle); });
    return copy;
}

template <typename T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    // (memcmp must not be given the null data() of an empty vector)
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expectSamePacking(const PackedScene& a, const PackedScene& b) {
    EXPECT_TRUE(sameBytes(a.triangles, b.triangles));
    EXPECT_TRUE(sameBytes(a.vertexPositions, b.vertexPositions));
    EXPECT_TRUE(sameBytes(a.vertexNormals, b.vertexNormals));
    EXPECT_TRUE(sameBytes(a.materials, b.materials));
    EXPECT_TRUE(sameBytes(a.bvhNodes, b.bvhNodes));
    EXPECT_TRUE(sameBytes(a.vertexPositions64, b.vertexPositions64));
    EXPECT_EQ(a.triangleOrder, b.triangleOrder);
}

// A unit cube of 12 triangles in 6 quads, smooth normals computed, one coloured corner and
// two materials.
const std::string kCube = "mtllib cube.mtl\n"
                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                          "v 0 0 1\nv 1 0 1 0.9 0.1 0.1\nv 1 1 1\nv 0 1 1\n"
                          "usemtl red\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\n"
                          "usemtl shiny\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
const std::string kCubeMtl = "newmtl red\nKd 0.8 0.1 0.1\n"
                             "newmtl shiny\nKd 0.2 0.2 0.2\nKs 0.5 0.5 0.5\nNs 50\n";

// The same cube in one material, no vertex coloured: its vertices, numbered as its corners
// first use them, pack in vertex order on all threads (scene_packing.cpp).
const std::string kPlainCube = "mtllib cube.mtl\n"
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                               "usemtl shiny\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\n"
                               "f 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

// The scene packs to the same arrays as its triangles written per vertex, in fp32 and fp64,
// with and without the hierarchy.
void expectSamePackingAsPerVertex(const Scene& scene) {
    const Scene perVertex = perVertexCopy(scene);
    ASSERT_EQ(perVertex.triangles.size(), triangleCount(scene));
    for (const Precision precision : {Precision::Fp32, Precision::Fp64}) {
        for (const Acceleration acceleration : {Acceleration::Bvh, Acceleration::None}) {
            SCOPED_TRACE(precision == Precision::Fp32 ? "fp32" : "fp64");
            expectSamePacking(packScene(scene, acceleration, precision),
                              packScene(perVertex, acceleration, precision));
        }
    }
}

} // namespace

TEST(Mesh, AModelsCornersShareVerticesAndItsFloorIsAMeshOfItsOwn) {
    // Two triangles of one flat quad with a normal given per position: 4 vertices, not 6.
    const Scene quad = modelScene("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                                  "f 1//1 2//1 3//1 4//1\n");
    ASSERT_EQ(quad.meshes.size(), 2u);
    EXPECT_TRUE(quad.triangles.empty());
    const Mesh& model = quad.meshes[0];
    EXPECT_EQ(model.triangles.size(), 2u);
    EXPECT_EQ(model.positions.size(), 4u);
    EXPECT_EQ(model.triangleLines, (std::vector<std::int64_t>{6, 6}));
    EXPECT_TRUE(model.colors.empty());
    const Mesh& floor = quad.meshes[1];
    EXPECT_EQ(floor.triangles.size(), 2u);
    EXPECT_EQ(floor.triangleLines, (std::vector<std::int64_t>{0, 0}));
    EXPECT_EQ(triangleCount(quad), 4u);
    EXPECT_EQ(triangleLines(quad), (std::vector<std::int64_t>{6, 6, 0, 0}));
    EXPECT_EQ(modelScene("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "", false).meshes.size(), 1u);
}

TEST(Mesh, CreasesSplitAVertexWhereTheNormalsDiffer) {
    // With flat faces (crease 0 is not the default, so the cube's 90-degree edges split at
    // the default 60): each corner of the cube is three vertices, one per face it meets.
    const Scene cube = modelScene(kCube, kCubeMtl, false);
    EXPECT_EQ(cube.meshes[0].positions.size(), 24u);
    EXPECT_EQ(cube.meshes[0].triangles.size(), 12u);
}

TEST(Mesh, TrianglesReadBackPerVertexWithTheirMaterialsAndColours) {
    const Scene cube = modelScene(kCube, kCubeMtl);
    const Mesh& mesh = cube.meshes[0];
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    bool sawColoured = false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Triangle triangle = triangleAt(cube, t);
        EXPECT_EQ(triangle.line, mesh.triangleLines[t]);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.triangles[t][k];
            EXPECT_EQ(triangle.vertices[k].position, mesh.positions[v]);
            EXPECT_EQ(triangle.vertices[k].normal, mesh.normals[v]);
            const Material& own = mesh.materials[mesh.triangleMaterials[t]].phong;
            const bool coloured = mesh.colors[v].w == 1.0;
            sawColoured |= coloured;
            EXPECT_EQ(triangle.vertices[k].material.diffuse,
                      coloured ? glm::dvec3(0.9, 0.1, 0.1) : own.diffuse);
            EXPECT_EQ(triangle.vertices[k].material.specular, own.specular);
        }
    }
    EXPECT_TRUE(sawColoured);
    EXPECT_THROW(triangleAt(cube, triangleCount(cube)), std::out_of_range);
}

TEST(Mesh, TheMaterialTableHoldsTheDiffuseTextureNamedByTheMtl) {
    const std::string mtl = "newmtl plain\nKd 0.5 0.5 0.5\n"
                            "newmtl wood\nmap_Kd -s 2 2 -clamp on -bm 0.5 textures/oak wood.png\n"
                            "newmtl odd\nmap_Kd -unknown 3 x.png\n"
                            "newmtl bare\nmap_Kd -o 1\n";
    const Scene scene = modelScene("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                   "usemtl wood\nf 1 2 3\n",
                                   mtl, false);
    const std::vector<MeshMaterial>& materials = scene.meshes[0].materials;
    ASSERT_EQ(materials.size(), 5u); // the default, then the library's four
    EXPECT_EQ(materials[1].diffuseTexture, "");
    EXPECT_EQ(materials[2].diffuseTexture, "textures/oak wood.png");
    EXPECT_EQ(materials[3].diffuseTexture, ""); // not an option of MTL's: no name read
    EXPECT_EQ(materials[4].diffuseTexture, ""); // options and no name
    EXPECT_EQ(scene.meshes[0].triangleMaterials[0], 2u);
    EXPECT_EQ(materials[2].phong.diffuse, defaultModelMaterial().phong.diffuse);
}

TEST(Mesh, AMeshOfOneMaterialPacksAsItsTrianglesPerVertex) {
    Scene cube = modelScene(kPlainCube, kCubeMtl);
    cube.spheres.push_back(Sphere{{0, 3, -6}, 0.5, {}, 9});
    expectSamePackingAsPerVertex(cube);
}

TEST(Mesh, PackingAMeshEqualsPackingItsTrianglesPerVertex) {
    Scene cube = modelScene(kCube, kCubeMtl);
    // A scene file's own triangle and sphere beside the meshes: numbered first.
    Triangle own;
    own.vertices[0].position = {-3, 0, -5};
    own.vertices[1].position = {-2, 0, -5};
    own.vertices[2].position = {-3, 1, -5};
    own.vertices[0].material.diffuse = {0.1, 0.2, 0.3};
    own.line = 4;
    cube.triangles.push_back(own);
    cube.spheres.push_back(Sphere{{0, 3, -6}, 0.5, {}, 9});
    expectSamePackingAsPerVertex(cube);
}

TEST(Mesh, AModelWhoseFacesAreItsTrianglesGivesTheSceneOfOneThatListsThem) {
    // The cube in triangles, read with its faces in its triangles (no face arrays), and the
    // same model with them listed: smooth normals everywhere (each position's faces averaged)
    // and the default crease give the same scene, to the byte.
    const std::string triangles = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                  "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
                                  "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    const SourceModel own = parseObj(triangles, "model.obj", [](const std::string& name) {
        return MtlFile{name, std::nullopt};
    });
    ASSERT_TRUE(own.triangles.facesAreTriangles());
    SourceModel listed = own;
    listed.triangles = SourceTriangles{};
    for (std::size_t t = 0; t < own.triangles.size(); ++t) {
        listed.triangles.push_back(own.triangles[t]);
        for (int c = 0; c < 3; ++c)
            listed.facePositions.push_back(own.triangles.positions(t)[c]);
        listed.faceStarts.push_back(listed.facePositions.size());
    }
    ASSERT_FALSE(listed.triangles.facesAreTriangles());
    ASSERT_EQ(faceCount(listed), 12u);
    for (const double crease : {60.0, 180.0}) {
        ModelSceneSetup setup;
        setup.creaseDegrees = crease;
        const Scene a = sceneFromModel(own, setup, "model.obj"),
                    b = sceneFromModel(listed, setup, "model.obj");
        EXPECT_EQ(a.meshes[0].positions.size(), crease == 180.0 ? 8u : 24u);
        expectSamePacking(packScene(a, Acceleration::Bvh, Precision::Fp32),
                          packScene(b, Acceleration::Bvh, Precision::Fp32));
    }
}
