// Model and scene files as users' files are: another format behind the expected name is
// named by its first bytes (PLY, STL, glTF, UTF-16 text), a material library that is
// missing is one warning that says how many faces fell back to the default material, a
// concave face is split by ear clipping (its area kept, its holes open), a model's faces
// are kept in its triangles until a face is not a triangle, and its colours once a position
// has one.
#include "model/model_bytes.h"
#include "model/obj_reader.h"
#include "model/ply_reader.h"
#include "model/polygon_triangulation.h"
#include "model/shared_positions.h"
#include "model/stl_reader.h"
#include "scene/file_format.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace std::string_literals;

std::string objError(const std::string& text) {
    try {
        parseObj(text, "m.obj", [](const std::string& name) {
            return MtlFile{name, std::nullopt};
        });
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

std::string sceneError(const std::string& text) {
    try {
        parseScene(text, "s.scene");
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

// The name of what otherFileFormat finds, or nothing.
std::optional<std::string> formatOf(std::string_view text) {
    const std::optional<OtherFormat> format = otherFileFormat(text);
    return format ? std::optional(formatName(*format)) : std::nullopt;
}

std::string binaryStl(std::uint32_t triangles) {
    std::string data(80, ' ');
    data.append(reinterpret_cast<const char*>(&triangles), 4);
    data.append(50 * std::size_t(triangles), '\0');
    return data;
}

} // namespace

TEST(ModelInput, OtherFormatsAreNamedByTheirFirstBytes) {
    EXPECT_EQ(formatOf("ply\nformat ascii 1.0\n"), "a PLY model");
    EXPECT_EQ(formatOf("ply\r\nformat binary_little_endian 1.0\r\n"), "a PLY model");
    EXPECT_EQ(formatOf("solid cube\n  facet normal 0 0 1\n"), "an STL model");
    EXPECT_EQ(formatOf(binaryStl(3)), "an STL model");
    EXPECT_EQ(formatOf("glTF\x02\0\0\0"s), "a binary glTF model (.glb)");
    EXPECT_EQ(formatOf("{\n  \"asset\": {\"version\": \"2.0\"}\n}"), "a glTF model");
    EXPECT_EQ(formatOf("\xFF\xFE#\0 \0"s), "UTF-16 text");
    EXPECT_EQ(formatOf("v\0 \0"
                       "0\0 \0"s),
              "UTF-16 text"); // little-endian, no mark
    EXPECT_EQ(formatOf("\0v\0 \0"
                       "0\0 "s),
              "UTF-16 text"); // big-endian, no mark
    // What is not one of them: the project's own formats and other bytes.
    EXPECT_EQ(formatOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), std::nullopt);
    EXPECT_EQ(formatOf("1\namb: 0 0 0\nlight\npos: 0 0 0\ncol: 1 1 1\n"), std::nullopt);
    EXPECT_EQ(formatOf("solid as a rock\n"), std::nullopt); // no facet: not STL
    EXPECT_EQ(formatOf(binaryStl(3) + "x"), std::nullopt);  // the size does not add up
    EXPECT_EQ(formatOf("2\na\0b"s), std::nullopt);          // binary, said so elsewhere
    EXPECT_EQ(formatOf(""), std::nullopt);
}

TEST(ModelInput, AnObjOrSceneFileOfAnotherFormatSaysWhatItIs) {
    EXPECT_EQ(objError("ply\nformat ascii 1.0\nelement vertex 3\n"),
              "m.obj: error: not an OBJ model: this is a PLY model, which is not read; convert it "
              "to OBJ first (for example with assimp export, Debian's assimp-utils)");
    EXPECT_EQ(sceneError("glTF\x02\0\0\0"s),
              "s.scene: error: not a scene file: this is a binary glTF model (.glb), which is not "
              "read; convert it to OBJ first (for example with assimp export, Debian's "
              "assimp-utils)");
    EXPECT_EQ(objError("\xFF\xFEv\0 \0"s),
              "m.obj: error: the file is UTF-16 text, and an OBJ model is read as UTF-8; convert "
              "it first: iconv -f UTF-16 -t UTF-8 'm.obj' > converted.obj");
    EXPECT_EQ(sceneError("1\0\n\0"s),
              "s.scene: error: the file is UTF-16 text, and a scene file is read as UTF-8; "
              "convert it first: iconv -f UTF-16 -t UTF-8 's.scene' > converted.scene");
}

TEST(ModelInput, AMissingLibraryIsOneWarningWithTheFacesThatFellBack) {
    const std::string obj = "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                            "f 1 2 3\n"                      // before any usemtl: not counted
                            "usemtl red\nf 1 2 3\nf 2 4 3\n" // two faces fell back
                            "usemtl blue\nf 1 2 4\n";        // and one more
    const SourceModel model = parseObj(obj, "m.obj", [](const std::string& name) {
        return MtlFile{name, std::nullopt};
    });
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_EQ(model.warnings[0], "m.obj:1: warning: material library gone.mtl not found; 3 of 4 "
                                 "faces use the default material");
    // Two missing libraries are named in that one warning; a name unknown while every
    // library was found is still its own warning.
    const SourceModel two = parseObj("mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                                     "m.obj", [](const std::string& name) {
                                         return MtlFile{name, std::nullopt};
                                     });
    ASSERT_EQ(two.warnings.size(), 1u);
    EXPECT_EQ(two.warnings[0], "m.obj:1: warning: material libraries a.mtl and b.mtl not found; 0 "
                               "of 1 faces use the default material");
    const SourceModel found = parseObj("mtllib here.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                       "usemtl nosuch\nf 1 2 3\n",
                                       "m.obj", [](const std::string& name) {
                                           return MtlFile{name, "newmtl red\nKd 1 0 0\n"};
                                       });
    ASSERT_EQ(found.warnings.size(), 1u);
    EXPECT_EQ(found.warnings[0],
              "m.obj:5: warning: unknown material 'nosuch'; default material used");
}

namespace {

double triangleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

double areaOf(const std::vector<glm::dvec3>& corners, const PolygonTriangles& split) {
    double area = 0.0;
    for (const auto& [a, b, c] : split.triangles)
        area += triangleArea(corners[a], corners[b], corners[c]);
    return area;
}

// Whether point lies inside (or on) the triangle a b c of the z = 0 plane.
bool covers(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p) {
    auto side = [](const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& q) {
        return (v.x - u.x) * (q.y - u.y) - (v.y - u.y) * (q.x - u.x);
    };
    const double d1 = side(a, b, p), d2 = side(b, c, p), d3 = side(c, a, p);
    return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}

// A ring of k corners outside and k inside, cut open along a bridge from outer corner 0
// to inner corner 0: 2k + 2 corners, the two bridge ends each twice.
std::vector<glm::dvec3> ring(int k, double outer, double inner, double z = 0.0) {
    std::vector<glm::dvec3> corners;
    for (int i = 0; i <= k; ++i) {
        const double a = 2.0 * M_PI * double(i % k) / k;
        corners.push_back({outer * std::cos(a), outer * std::sin(a), z});
    }
    for (int i = 0; i <= k; ++i) { // the other way round
        const double a = -2.0 * M_PI * double(i % k) / k;
        corners.push_back({inner * std::cos(a), inner * std::sin(a), z});
    }
    return corners;
}

double shoelace(const std::vector<glm::dvec3>& corners) {
    double twice = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 &a = corners[i], &b = corners[(i + 1) % corners.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return std::abs(twice) / 2.0;
}

} // namespace

TEST(PolygonTriangulation, ConvexPolygonsAreTheFanTheyAlwaysWere) {
    const std::vector<glm::dvec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const PolygonTriangles split = triangulatePolygon(quad);
    EXPECT_EQ(split.triangles, (std::vector<std::array<std::size_t, 3>>{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_FALSE(split.fannedConcave);
    // A bent quad stays a fan, with no word: only concave ones are checked for flatness.
    const std::vector<glm::dvec3> bent = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}};
    EXPECT_EQ(triangulatePolygon(bent).triangles.size(), 2u);
    EXPECT_FALSE(triangulatePolygon(bent).fannedConcave);
}

TEST(PolygonTriangulation, ConcavePlanarPolygonsKeepTheirAreaAndTheirHoles) {
    // The 66-corner ring: 64 triangles of exactly the ring's area, none over its hole.
    const std::vector<glm::dvec3> corners = ring(32, 1.0, 0.5, -2.0);
    ASSERT_EQ(corners.size(), 66u);
    const PolygonTriangles split = triangulatePolygon(corners);
    EXPECT_FALSE(split.fannedConcave);
    EXPECT_EQ(split.triangles.size(), 64u);
    EXPECT_NEAR(areaOf(corners, split), shoelace(corners), 1e-12);
    for (const auto& [a, b, c] : split.triangles)
        EXPECT_FALSE(covers(corners[a], corners[b], corners[c], {0.0, 0.0, -2.0}));
    // A ten-pointed star, turned the other way and tilted out of every axis plane.
    std::vector<glm::dvec3> star;
    for (int i = 0; i < 10; ++i) {
        const double r = i % 2 ? 0.4 : 1.0, a = -2.0 * M_PI * i / 10.0;
        star.push_back({r * std::cos(a), r * std::sin(a), 0.0});
    }
    const double flat = areaOf(star, triangulatePolygon(star));
    EXPECT_NEAR(flat, shoelace(star), 1e-12);
    for (glm::dvec3& p : star)
        p = glm::dvec3(p.x, 0.6 * p.y - 0.8 * p.z, 0.8 * p.y + 0.6 * p.z) + glm::dvec3(3, -1, 2);
    const PolygonTriangles tilted = triangulatePolygon(star);
    EXPECT_FALSE(tilted.fannedConcave);
    EXPECT_EQ(tilted.triangles.size(), 8u);
    EXPECT_NEAR(areaOf(star, tilted), flat, 1e-12);
}

TEST(PolygonTriangulation, ConcavePolygonsOutOfTheirPlaneOrCrossingThemselvesAreFanned) {
    std::vector<glm::dvec3> bent = ring(8, 1.0, 0.5);
    bent[3].z = 0.1; // far beyond 1e-4 of the ring's reach
    const PolygonTriangles split = triangulatePolygon(bent);
    EXPECT_TRUE(split.fannedConcave);
    EXPECT_EQ(split.triangles.front(), (std::array<std::size_t, 3>{0, 1, 2}));
    // A pentagram drawn as one polygon crosses itself: no ear can be cut where it folds.
    std::vector<glm::dvec3> pentagram;
    for (int i = 0; i < 5; ++i) {
        const double a = 2.0 * M_PI * (2 * i) / 5.0;
        pentagram.push_back({std::cos(a), std::sin(a), 0.0});
    }
    pentagram.push_back({0.5, 0.5, 0.0}); // and a sixth corner, so it is not all convex turns
    const PolygonTriangles crossing = triangulatePolygon(pentagram);
    EXPECT_EQ(crossing.triangles.size(), 4u);
    EXPECT_TRUE(crossing.fannedConcave);
}

TEST(ModelInput, AConcaveFaceOutOfItsPlaneIsOneWarning) {
    std::string obj;
    std::vector<glm::dvec3> bent = ring(8, 1.0, 0.5);
    bent[3].z = 0.1;
    for (const glm::dvec3& p : bent)
        obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) +
               "\n";
    std::string face = "f";
    for (std::size_t i = 1; i <= bent.size(); ++i)
        face += " " + std::to_string(i);
    obj += face + "\n" + face + "\n";
    const SourceModel model = parseObj(obj, "m.obj", [](const std::string& name) {
        return MtlFile{name, std::nullopt};
    });
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_EQ(model.warnings[0], "m.obj:19: warning: 2 concave face(s) not in one plane, or "
                                 "crossing themselves, split as fans from their first corner");
}

// A model's triangles keep normal and texture coordinate indices only once some corner has
// one; a corner before that has none, one after that keeps its own, and the model crosses
// from a child process (model_bytes.h) as it was, first triangle included.
TEST(SourceTriangles, NormalsAndTexcoordsAppearWithTheFirstCornerThatHasOne) {
    SourceModel model;
    model.positions.assign(4, glm::dvec3(0.0));
    model.positionLines.assign(4, 1);
    model.normals.assign(1, glm::dvec3(0.0, 0.0, 1.0));
    model.texcoords.assign(3, glm::dvec2(0.5));
    model.facePositions = {0, 1, 2, 0, 2, 3, 1, 2, 3};
    model.faceStarts = {0, 3, 6, 9};
    model.materials = {defaultModelMaterial()};
    auto corner = [](std::uint32_t position, std::uint32_t normal, std::uint32_t texcoord) {
        return SourceCorner{position, normal, texcoord};
    };
    model.triangles.push_back(
        {{corner(0, kNoNormal, 0), corner(1, kNoNormal, 1), corner(2, kNoNormal, kNoTexcoord)},
         0,
         0,
         7});
    EXPECT_TRUE(model.triangles.anyTexcoord());
    EXPECT_FALSE(model.triangles.anyNormal());
    model.triangles.push_back(
        {{corner(0, 0, kNoTexcoord), corner(2, kNoNormal, 2), corner(3, 0, 1)}, 0, 1, 8});
    model.triangles.push_back(
        {{corner(1, kNoNormal, kNoTexcoord), corner(2, kNoNormal, kNoTexcoord),
          corner(3, kNoNormal, kNoTexcoord)},
         0,
         2,
         9});
    EXPECT_TRUE(model.triangles.anyNormal());
    for (const SourceModel& read : {model, modelFromBytes(modelBytes(model))}) {
        ASSERT_EQ(read.triangles.size(), 3u);
        const SourceTriangle first = read.triangles[0], second = read.triangles[1],
                             third = read.triangles[2];
        EXPECT_EQ(first.corners[0].texcoord, 0u);
        EXPECT_EQ(first.corners[1].texcoord, 1u);
        EXPECT_EQ(first.corners[2].texcoord, kNoTexcoord);
        EXPECT_EQ(first.corners[0].normal, kNoNormal);
        EXPECT_EQ(second.corners[0].normal, 0u);
        EXPECT_EQ(second.corners[1].normal, kNoNormal);
        EXPECT_EQ(second.corners[2].normal, 0u);
        EXPECT_EQ(second.corners[2].texcoord, 1u);
        EXPECT_EQ(third.corners[2].position, 3u);
        EXPECT_EQ(third.corners[2].normal, kNoNormal);
        EXPECT_EQ(third.corners[2].texcoord, kNoTexcoord);
        EXPECT_EQ(second.face, 1u);
        EXPECT_EQ(third.line, 9);
    }
}

namespace {

// Each face's positions, "a,b,c" and " | " between faces.
std::string facesOf(const SourceModel& model) {
    std::string words;
    for (std::size_t f = 0; f < faceCount(model); ++f) {
        const std::span<const std::uint32_t> corners = facePositions(model, f);
        for (std::size_t c = 0; c < corners.size(); ++c)
            words += (c > 0 ? "," : f > 0 ? " | " : "") + std::to_string(corners[c]);
    }
    return words;
}

std::string asciiPly(const std::string& faces, int faceCount) {
    return "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
           "property float z\nelement face " +
           std::to_string(faceCount) +
           "\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n" +
           faces;
}

} // namespace

// Readers that add faces one by one keep them in the triangles while every face is a
// triangle, and list them all, the earlier ones too, from the first that is not.
TEST(SourceTriangles, FacesAreTheTrianglesUntilThePolygon) {
    const SourceModel triangles = readPly(asciiPly("3 0 1 2\n3 0 2 3\n3 0 3 4\n", 3), "m.ply");
    EXPECT_TRUE(triangles.triangles.facesAreTriangles());
    EXPECT_TRUE(triangles.facePositions.empty());
    EXPECT_EQ(facesOf(triangles), "0,1,2 | 0,2,3 | 0,3,4");

    const SourceModel polygon =
        readPly(asciiPly("3 0 1 2\n3 0 2 3\n4 0 1 2 3\n3 0 3 4\n", 4), "m.ply");
    EXPECT_FALSE(polygon.triangles.facesAreTriangles());
    EXPECT_EQ(facesOf(polygon), "0,1,2 | 0,2,3 | 0,1,2,3 | 0,3,4");
    ASSERT_EQ(polygon.triangles.size(), 5u);
    std::vector<std::uint32_t> faces;
    for (std::size_t t = 0; t < 5; ++t)
        faces.push_back(polygon.triangles.face(t));
    EXPECT_EQ(faces, (std::vector<std::uint32_t>{0, 1, 2, 2, 3}));

    // Across a child process too (model_bytes.h), either way.
    for (const SourceModel* model : {&triangles, &polygon}) {
        const SourceModel crossed = modelFromBytes(modelBytes(*model));
        EXPECT_EQ(crossed.triangles.facesAreTriangles(), model->triangles.facesAreTriangles());
        EXPECT_EQ(facesOf(crossed), facesOf(*model));
    }
}

// A model keeps no colours until a position has one (32 bytes a position): PLY without
// colour properties, STL and the shared positions of STL and assimp's models; from the
// first coloured position on, every position has its colour or none, the first one too.
TEST(ModelInput, ColoursOnlyOnceAPositionHasOne) {
    EXPECT_TRUE(readPly(asciiPly("3 0 1 2\n", 1), "m.ply").colors.empty());
    EXPECT_TRUE(readStl(binaryStl(2), "m.stl").colors.empty());
    for (const bool firstColoured : {false, true}) {
        SourceModel model;
        SharedPositions shared(model, 4);
        const std::optional<glm::vec3> red = glm::vec3(1.0f, 0.0f, 0.0f);
        shared.add({0, 0, 0}, firstColoured ? red : std::nullopt, 1);
        shared.add({1, 0, 0}, std::nullopt, 2);
        EXPECT_EQ(model.colors.empty(), !firstColoured);
        shared.add({2, 0, 0}, red, 3);
        shared.add({3, 0, 0}, std::optional(glm::vec3(NAN, 0.0f, 0.0f)), 4); // not finite: none
        ASSERT_EQ(model.colors.size(), 4u);
        EXPECT_EQ(model.colors[0].has_value(), firstColoured);
        EXPECT_FALSE(model.colors[1]);
        EXPECT_EQ(model.colors[2], std::optional(glm::dvec3(1.0, 0.0, 0.0)));
        EXPECT_FALSE(model.colors[3]);
    }
}
