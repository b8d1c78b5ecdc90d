// Model and scene files as users' files are: another format behind the expected name is
// named by its first bytes (PLY, STL, glTF, UTF-16 text), and a material library that is
// missing is one warning that says how many faces fell back to the default material.
#include "scene/file_format.h"
#include "scene/obj_reader.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

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

std::string binaryStl(std::uint32_t triangles) {
    std::string data(80, ' ');
    data.append(reinterpret_cast<const char*>(&triangles), 4);
    data.append(50 * std::size_t(triangles), '\0');
    return data;
}

} // namespace

TEST(ModelInput, OtherFormatsAreNamedByTheirFirstBytes) {
    EXPECT_EQ(otherFileFormat("ply\nformat ascii 1.0\n"), "a PLY model");
    EXPECT_EQ(otherFileFormat("ply\r\nformat binary_little_endian 1.0\r\n"), "a PLY model");
    EXPECT_EQ(otherFileFormat("solid cube\n  facet normal 0 0 1\n"), "an STL model");
    EXPECT_EQ(otherFileFormat(binaryStl(3)), "an STL model");
    EXPECT_EQ(otherFileFormat("glTF\x02\0\0\0"s), "a binary glTF model (.glb)");
    EXPECT_EQ(otherFileFormat("{\n  \"asset\": {\"version\": \"2.0\"}\n}"), "a glTF model");
    EXPECT_EQ(otherFileFormat("\xFF\xFE#\0 \0"s), "UTF-16 text");
    EXPECT_EQ(otherFileFormat("v\0 \0"
                              "0\0 \0"s),
              "UTF-16 text"); // little-endian, no mark
    EXPECT_EQ(otherFileFormat("\0v\0 \0"
                              "0\0 "s),
              "UTF-16 text"); // big-endian, no mark
    // What is not one of them: the project's own formats and other bytes.
    EXPECT_EQ(otherFileFormat("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), std::nullopt);
    EXPECT_EQ(otherFileFormat("1\namb: 0 0 0\nlight\npos: 0 0 0\ncol: 1 1 1\n"), std::nullopt);
    EXPECT_EQ(otherFileFormat("solid as a rock\n"), std::nullopt); // no facet: not STL
    EXPECT_EQ(otherFileFormat(binaryStl(3) + "x"), std::nullopt);  // the size does not add up
    EXPECT_EQ(otherFileFormat("2\na\0b"s), std::nullopt);          // binary, said so elsewhere
    EXPECT_EQ(otherFileFormat(""), std::nullopt);
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
    const ObjModel model = parseObj(obj, "m.obj", [](const std::string& name) {
        return MtlFile{name, std::nullopt};
    });
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_EQ(model.warnings[0], "m.obj:1: warning: material library gone.mtl not found; 3 of 4 "
                                 "faces use the default material");
    // Two missing libraries are named in that one warning; a name unknown while every
    // library was found is still its own warning.
    const ObjModel two = parseObj("mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                                  "m.obj", [](const std::string& name) {
                                      return MtlFile{name, std::nullopt};
                                  });
    ASSERT_EQ(two.warnings.size(), 1u);
    EXPECT_EQ(two.warnings[0], "m.obj:1: warning: material libraries a.mtl and b.mtl not found; 0 "
                               "of 1 faces use the default material");
    const ObjModel found = parseObj("mtllib here.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "usemtl nosuch\nf 1 2 3\n",
                                    "m.obj", [](const std::string& name) {
                                        return MtlFile{name, "newmtl red\nKd 1 0 0\n"};
                                    });
    ASSERT_EQ(found.warnings.size(), 1u);
    EXPECT_EQ(found.warnings[0],
              "m.obj:5: warning: unknown material 'nosuch'; default material used");
}
