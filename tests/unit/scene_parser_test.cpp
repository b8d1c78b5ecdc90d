// The scene parser from strings: every accepted form, every error with its exact
// message, the warnings, and the sample scenes of the classic assignment.
#include "model/scene_file.h"
#include "scene/scene_lexer.h"
#include "scene/scene_loader.h"
#include "scene/warning_summary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

Scene parse(std::string_view text) {
    return parseScene(text, "t.scene");
}

// The full what() of the error that parsing raises, or a marker if it succeeds.
std::string errorOf(std::string_view text) {
    try {
        parse(text);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(parsed without error)";
}

// One valid object of each kind, as in test1.scene and test2.scene; the tests
// plant errors in them with replaced(). header(n) + objects is a whole scene.
const std::string sphereText = "sphere\n"
                               "pos: 0.0 0.0 -3.0\n"
                               "rad: 1\n"
                               "dif: 0.3 0.3 0.3\n"
                               "spe: 0.5 0.5 0.5\n"
                               "shi: 1\n";
const std::string lightText = "light\n"
                              "pos: 0 0 0\n"
                              "col: 1 1 1\n";
const std::string triangleText = "triangle\n"
                                 "pos: -1.2 0 -2\n"
                                 "nor: 0 0 1\n"
                                 "dif: 0.5 0 0\n"
                                 "spe: 0.2 0.2 0.2\n"
                                 "shi: 50\n"
                                 "pos: -0.2 0 -2\n"
                                 "nor: 0 0 1\n"
                                 "dif: 0 0.5 0\n"
                                 "spe: 0.2 0.2 0.2\n"
                                 "shi: 40\n"
                                 "pos: -0.7 1 -2\n"
                                 "nor: 0 0 1\n"
                                 "dif: 0 0 0.5\n"
                                 "spe: 0.1 0.2 0.3\n"
                                 "shi: 30\n";

std::string header(int count) {
    return std::to_string(count) + "\namb: 0.3 0.3 0.3\n";
}

// Replaces the first occurrence of `from` in `text`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

// ---------------------------------------------------------------- valid input

TEST(SceneParser, ParsesTest1WithExactValues) {
    const Scene scene = parse(header(2) + sphereText + lightText);
    EXPECT_EQ(scene.ambient, glm::dvec3(0.3));
    ASSERT_EQ(scene.spheres.size(), 1u);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_TRUE(scene.triangles.empty());
    EXPECT_TRUE(scene.warnings.empty());
    const Sphere& s = scene.spheres[0];
    EXPECT_EQ(s.center, glm::dvec3(0.0, 0.0, -3.0));
    EXPECT_EQ(s.radius, 1.0);
    EXPECT_EQ(s.material.diffuse, glm::dvec3(0.3));
    EXPECT_EQ(s.material.specular, glm::dvec3(0.5));
    EXPECT_EQ(s.material.shininess, 1.0);
    EXPECT_EQ(scene.lights[0].position, glm::dvec3(0.0));
    EXPECT_EQ(scene.lights[0].color, glm::dvec3(1.0));
}

TEST(SceneParser, TriangleKeepsPerVertexMaterials) {
    const Scene scene = parse(header(1) + triangleText);
    ASSERT_EQ(scene.triangles.size(), 1u);
    const Triangle& t = scene.triangles[0];
    EXPECT_EQ(t.vertices[0].position, glm::dvec3(-1.2, 0, -2));
    EXPECT_EQ(t.vertices[1].position, glm::dvec3(-0.2, 0, -2));
    EXPECT_EQ(t.vertices[2].position, glm::dvec3(-0.7, 1, -2));
    for (const Vertex& v : t.vertices)
        EXPECT_EQ(v.normal, glm::dvec3(0, 0, 1));
    EXPECT_EQ(t.vertices[0].material.diffuse, glm::dvec3(0.5, 0, 0));
    EXPECT_EQ(t.vertices[1].material.diffuse, glm::dvec3(0, 0.5, 0));
    EXPECT_EQ(t.vertices[2].material.diffuse, glm::dvec3(0, 0, 0.5));
    EXPECT_EQ(t.vertices[2].material.specular, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(t.vertices[0].material.shininess, 50.0);
    EXPECT_EQ(t.vertices[1].material.shininess, 40.0);
    EXPECT_EQ(t.vertices[2].material.shininess, 30.0);
    EXPECT_TRUE(scene.warnings.empty());
}

// The one optional field: the mirror share after shi:, 1 (the classic model) when absent.
TEST(SceneParser, TheMirrorShareIsOptionalAndOneWithoutIt) {
    const Scene plain = parse(header(2) + sphereText + triangleText);
    EXPECT_EQ(plain.spheres[0].material.mirror, 1.0);
    for (const Vertex& v : plain.triangles[0].vertices)
        EXPECT_EQ(v.material.mirror, 1.0);
    const Scene shared = parse(header(2) + replaced(sphereText, "shi: 1", "shi: 1\nmir: 0") +
                               replaced(replaced(triangleText, "shi: 40", "shi: 40 MIR: 0.25"),
                                        "shi: 30", "shi: 30\nmir: 1"));
    EXPECT_EQ(shared.spheres[0].material.mirror, 0.0);
    EXPECT_EQ(shared.triangles[0].vertices[0].material.mirror, 1.0);
    EXPECT_EQ(shared.triangles[0].vertices[1].material.mirror, 0.25);
    EXPECT_EQ(shared.triangles[0].vertices[2].material.mirror, 1.0);
    EXPECT_EQ(mirrorWeight(shared.triangles[0].vertices[1].material), glm::dvec3(0.2 * 0.25));
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "shi: 1", "shi: 1 mir: 1.5")),
              "t.scene:8: error: the sphere's mirror share must be between 0 and 1, found 1.5");
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "shi: 1", "shi: 1 mir: x")),
              "t.scene:8: error: expected a number for the sphere's mirror share, found 'x'");
}

TEST(SceneParser, KeepsObjectsInFileOrderPerKind) {
    const Scene scene = parse(header(5) + lightText + sphereText + triangleText +
                              replaced(sphereText, "rad: 1", "rad: 2") +
                              replaced(lightText, "col: 1 1 1", "col: 0.5 0.5 0.5"));
    ASSERT_EQ(scene.spheres.size(), 2u);
    ASSERT_EQ(scene.triangles.size(), 1u);
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.spheres[1].radius, 2.0);
    EXPECT_EQ(scene.lights[1].color, glm::dvec3(0.5));
}

// Each object keeps the line of its keyword (the pixel story names it), whatever the line
// endings and blank lines, and when the text is split among threads.
TEST(SceneParser, ObjectsKeepTheLineOfTheirKeyword) {
    const std::string text = header(4) + "\n" + lightText + sphereText + "\r\n\r\n" + triangleText +
                             "\n\n\n" + replaced(sphereText, "rad: 1", "rad: 2");
    const auto lineOf = [&](std::size_t at) {
        return std::int64_t(1 + std::count(text.begin(), text.begin() + at, '\n'));
    };
    const std::size_t light = text.find("light"), sphere = text.find("sphere");
    const std::size_t triangle = text.find("triangle"), second = text.find("sphere", sphere + 1);
    for (unsigned threads : {1u, 2u, 3u, 5u}) {
        const Scene scene = parseScene(text, "t.scene", {threads, 1});
        ASSERT_EQ(scene.spheres.size(), 2u);
        EXPECT_EQ(scene.lights[0].line, lineOf(light)) << threads;
        EXPECT_EQ(scene.spheres[0].line, lineOf(sphere)) << threads;
        EXPECT_EQ(scene.triangles[0].line, lineOf(triangle)) << threads;
        EXPECT_EQ(scene.spheres[1].line, lineOf(second)) << threads;
    }
    EXPECT_EQ(lineOf(light), 4); // the header's two lines, then a blank one
}

TEST(SceneParser, KeywordsAndKeysAreCaseInsensitive) {
    const Scene scene = parse("2\nAMB: 0.1 0.2 0.3\nSphere\nPOS: 1 2 3\nRad: 4\nDIF: 0 0 0\n"
                              "sPe: 0 0 0\nShI: 5\nLIGHT\nPos: 0 0 0\nCOL: 1 1 1\n");
    EXPECT_EQ(scene.ambient, glm::dvec3(0.1, 0.2, 0.3));
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.spheres[0].radius, 4.0);
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(parse("1\namb: 0 0 0\nTRIANGLE\n" + triangleText.substr(9)).triangles.size(), 1u);
}

TEST(SceneParser, AnyWhitespaceSeparatesTokens) {
    // Tabs, runs of spaces, blank lines, CRLF, trailing spaces, no final newline,
    // and the whole file on one line all read the same.
    const std::string reference = header(2) + sphereText + lightText;
    std::string crlf;
    for (char c : reference)
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const std::string variants[] = {
        crlf,
        replaced(reference, "\n", "\r\n"), // mixed endings
        "\n\n  2 \n\n\tamb:\t0.3   0.3 0.3  \n\n" + sphereText + "\n\n" + lightText + "\n\n\n",
        "2 amb: 0.3 0.3 0.3 sphere pos: 0.0 0.0 -3.0 rad: 1 dif: 0.3 0.3 0.3 spe: 0.5 0.5 0.5 "
        "shi: 1 light pos: 0 0 0 col: 1 1 1",
        "2\ramb: 0.3 0.3 0.3\r" + sphereText + lightText, // old Mac line ends
        "2\vamb: 0.3 0.3 0.3\f" + sphereText + lightText,
    };
    for (const std::string& text : variants) {
        const Scene scene = parse(text);
        ASSERT_EQ(scene.spheres.size(), 1u) << text;
        EXPECT_EQ(scene.spheres[0].center, glm::dvec3(0.0, 0.0, -3.0));
        EXPECT_EQ(scene.ambient, glm::dvec3(0.3));
        EXPECT_EQ(scene.lights.size(), 1u);
    }
}

TEST(SceneParser, SkipsUtf8ByteOrderMark) {
    const Scene scene = parse("\xEF\xBB\xBF" + header(1) + lightText);
    EXPECT_EQ(scene.lights.size(), 1u);
}

TEST(SceneParser, AcceptsEveryDecimalNumberForm) {
    const auto position = [](const std::string& x, const std::string& y, const std::string& z) {
        const Scene scene =
            parse("1\namb: 0 0 0\nlight\npos: " + x + " " + y + " " + z + "\ncol: 1 1 1\n");
        return scene.lights.at(0).position;
    };
    EXPECT_EQ(position("-2.6748e-08", ".44", "5"), glm::dvec3(-2.6748e-08, 0.44, 5.0));
    EXPECT_EQ(position("1.", "-.5", "+3"), glm::dvec3(1.0, -0.5, 3.0));
    EXPECT_EQ(position("1E3", "1e+2", "+.25e-1"), glm::dvec3(1000.0, 100.0, 0.025));
    EXPECT_EQ(position("-0.35315093486933696", "0.4699999988079071", "007"),
              glm::dvec3(-0.35315093486933696, 0.4699999988079071, 7.0));
    EXPECT_EQ(position("1.7976931348623157e308", "4e-320", "0"),
              glm::dvec3(1.7976931348623157e308, 4e-320, 0.0));
    const glm::dvec3 zeros = position("-0", "1e-400", "-0.0000001e-400"); // underflow reads as zero
    EXPECT_EQ(zeros, glm::dvec3(0.0));
    EXPECT_TRUE(std::signbit(zeros.x));
    EXPECT_FALSE(std::signbit(zeros.y));
    EXPECT_TRUE(std::signbit(zeros.z));
}

TEST(SceneParser, ZeroObjectsAndLightsOnly) {
    const Scene empty = parse("0\namb: 0 0 0\n");
    EXPECT_TRUE(empty.spheres.empty() && empty.triangles.empty() && empty.lights.empty());
    const Scene lights = parse(header(3) + lightText + lightText + lightText);
    EXPECT_EQ(lights.lights.size(), 3u);
    EXPECT_TRUE(lights.spheres.empty() && lights.triangles.empty());
}

TEST(SceneParser, BrightLightsAndAmbientNeedNoWarning) {
    const Scene scene =
        parse("1\namb: 1.5 2 0\n" + replaced(lightText, "col: 1 1 1", "col: 10 20 30"));
    EXPECT_EQ(scene.ambient, glm::dvec3(1.5, 2.0, 0.0));
    EXPECT_EQ(scene.lights[0].color, glm::dvec3(10, 20, 30));
    EXPECT_TRUE(scene.warnings.empty());
}

// ------------------------------------------------------------------- warnings

TEST(SceneParser, WarnsAboutDiffuseOrSpecularAboveOne) {
    const Scene scene =
        parse(header(2) + replaced(sphereText, "spe: 0.5 0.5 0.5", "spe: 1.5 2 0.5") +
              replaced(triangleText, "dif: 0 0 0.5", "dif: 0 0 1.0001"));
    EXPECT_EQ(scene.spheres[0].material.specular, glm::dvec3(1.5, 2.0, 0.5)); // used as given
    EXPECT_EQ(scene.triangles[0].vertices[2].material.diffuse, glm::dvec3(0, 0, 1.0001));
    ASSERT_EQ(scene.warnings.size(), 2u);
    EXPECT_EQ(scene.warnings[0],
              "t.scene:7: warning: the sphere's 'spe:' 1.5 is above 1; used as given");
    EXPECT_EQ(
        scene.warnings[1],
        "t.scene:22: warning: the triangle's vertex 3 'dif:' 1.0001 is above 1; used as given");
}

TEST(SceneParser, WarnsAboutDegenerateTriangles) {
    std::string text = header(2) + triangleText + triangleText;
    text = replaced(text, "pos: -0.7 1 -2", "pos: -0.7 0 -2"); // first triangle: collinear
    text = replaced(text, "nor: 0 0 1\ndif: 0 0.5 0", "nor: 0 0 0\ndif: 0 0.5 0");
    text = replaced(text, "nor: 0 0 1\ndif: 0 0.5 0", "nor: -0 0 0\ndif: 0 0.5 0");
    const Scene scene = parse(text);
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].vertices[1].normal, glm::dvec3(0.0)); // kept as given
    ASSERT_EQ(scene.warnings.size(), 3u);
    EXPECT_EQ(scene.warnings[0],
              "t.scene:10: warning: the triangle's vertex 2 normal has zero length");
    EXPECT_EQ(
        scene.warnings[1],
        "t.scene:3: warning: the triangle has zero area (its vertices are collinear or coincide)");
    EXPECT_EQ(scene.warnings[2],
              "t.scene:26: warning: the triangle's vertex 2 normal has zero length");
}

// --------------------------------------------------------------------- errors

TEST(SceneParserError, CarriesFileLineAndMessage) {
    try {
        parseScene("1\namb: 0 0 0\ncube\n", "dir/my.scene");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.file, "dir/my.scene");
        EXPECT_EQ(e.line, 3);
        EXPECT_EQ(e.message,
                  "unknown object keyword 'cube' (expected 'sphere', 'triangle' or 'light')");
        EXPECT_STREQ(e.what(), "dir/my.scene:3: error: unknown object keyword 'cube' (expected "
                               "'sphere', 'triangle' or 'light')");
    }
    const SceneError whole("f.scene", 0, "the file is empty");
    EXPECT_STREQ(whole.what(), "f.scene: error: the file is empty");
}

TEST(SceneParserError, EmptyFile) {
    EXPECT_EQ(errorOf(""), "t.scene: error: the file is empty");
    EXPECT_EQ(errorOf(" \r\n\t\n\n"), "t.scene: error: the file is empty");
    EXPECT_EQ(errorOf("\xEF\xBB\xBF"), "t.scene: error: the file is empty");
}

TEST(SceneParserError, BinaryFile) {
    using namespace std::string_literals;
    EXPECT_EQ(errorOf("2\na\0b"s), "t.scene: error: the file is binary (NUL byte at offset 3)");
    EXPECT_EQ(errorOf("\x7F"
                      "ELF\x02\x01"),
              "t.scene: error: the file is binary (control byte 0x7f at offset 0)");
    EXPECT_EQ(errorOf("2\n\x1b[0m"),
              "t.scene: error: the file is binary (control byte 0x1b at offset 2)");
    EXPECT_EQ(errorOf("2\n\xFF\xFE"),
              "t.scene: error: the file is binary (invalid UTF-8 at offset 2)");
    EXPECT_EQ(errorOf("2 \xC3"),
              "t.scene: error: the file is binary (invalid UTF-8 at offset 2)"); // cut short
    EXPECT_EQ(errorOf("2 \xC0\x80"),
              "t.scene: error: the file is binary (invalid UTF-8 at offset 2)"); // overlong
    EXPECT_EQ(errorOf("2 \xED\xA0\x80"),
              "t.scene: error: the file is binary (invalid UTF-8 at offset 2)"); // surrogate
    EXPECT_EQ(errorOf("\xEF\xBB\xBF\xEF\xBB"),
              "t.scene: error: the file is binary (invalid UTF-8 at offset 3)");
    // Well-formed UTF-8 is text: it reaches the parser, which quotes it.
    EXPECT_EQ(errorOf("1\namb: 0 0 0\nsph\xC3\xA8re\n"),
              "t.scene:3: error: unknown object keyword 'sph\xC3\xA8re' (expected 'sphere', "
              "'triangle' or 'light')");
}

TEST(SceneParserError, ObjectCountIsAPlainNonNegativeInteger) {
    for (const char* bad : {"12.0", "1.2e1", "-1", "+3", "0x10", "abc", "amb:", "2,"}) {
        EXPECT_EQ(errorOf(std::string(bad) + "\namb: 0 0 0\n"),
                  "t.scene:1: error: expected the object count (a non-negative integer) at the "
                  "start of the file, found '" +
                      std::string(bad) + "'");
    }
    EXPECT_EQ(errorOf("\n\n\xEF\xBB\xBF"
                      "1\n"),
              "t.scene:3: error: expected the object count (a "
              "non-negative integer) at the start of the file, "
              "found '\xEF\xBB\xBF"
              "1'"); // a BOM only counts at the start
    EXPECT_EQ(errorOf("18446744073709551616\namb: 0 0 0\n"),
              "t.scene:1: error: the object count '18446744073709551616' is too large");
}

TEST(SceneParserError, Ambient) {
    EXPECT_EQ(errorOf("1\nambient: 0 0 0\n"),
              "t.scene:2: error: expected 'amb:' after the object count, found 'ambient:'");
    EXPECT_EQ(
        errorOf("1\n"),
        "t.scene:1: error: expected 'amb:' after the object count, found the end of the file");
    EXPECT_EQ(errorOf("1\namb: 0.1 0.1\nlight\n"),
              "t.scene:3: error: expected a number for the ambient colour, found 'light'");
    EXPECT_EQ(errorOf("0\namb: 0.1 -0.1 0\n"),
              "t.scene:2: error: negative colour value -0.1 in the ambient colour");
}

TEST(SceneParserError, UnknownObjectKeyword) {
    EXPECT_EQ(errorOf(header(2) + lightText + "\n\ncube\n"),
              "t.scene:8: error: unknown object keyword 'cube' (expected 'sphere', 'triangle' or "
              "'light')");
    // A sixth number on a line ends the field and is then taken for the next object.
    EXPECT_EQ(errorOf(header(2) + replaced(sphereText, "shi: 1", "shi: 1 2") + lightText),
              "t.scene:8: error: unknown object keyword '2' (expected 'sphere', 'triangle' or "
              "'light')");
    EXPECT_EQ(
        errorOf(header(1) + std::string(100, 'x')),
        "t.scene:3: error: unknown object keyword 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...' "
        "(expected 'sphere', 'triangle' or 'light')");
}

TEST(SceneParserError, MissingOrMisspelledKey) {
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "rad:", "radius:")),
              "t.scene:5: error: expected 'rad:' after the sphere's position, found 'radius:'");
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "pos:", "center:")),
              "t.scene:4: error: expected 'pos:' after 'sphere', found 'center:'");
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "dif:", "dif")),
              "t.scene:6: error: expected 'dif:' after the sphere's radius, found 'dif'");
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "spe:", "shi:")),
              "t.scene:7: error: expected 'spe:' after the sphere's 'dif:', found 'shi:'");
    EXPECT_EQ(
        errorOf(header(1) + replaced(sphereText, "shi: 1\n", "")),
        "t.scene:7: error: expected 'shi:' after the sphere's 'spe:', found the end of the file");
    EXPECT_EQ(errorOf(header(1) + replaced(lightText, "col:", "dif:")),
              "t.scene:5: error: expected 'col:' after the light's position, found 'dif:'");
    EXPECT_EQ(
        errorOf(header(1) + replaced(triangleText, "nor: 0 0 1\n", "")),
        "t.scene:5: error: expected 'nor:' after the triangle's vertex 1 position, found 'dif:'");
    EXPECT_EQ(
        errorOf(header(1) + replaced(triangleText, "shi: 40", "shi: 40 1")),
        "t.scene:13: error: expected 'pos:' after the triangle's vertex 2 shininess, found '1' "
        "(a triangle has three vertices)");
    // A triangle with two vertices runs into the next object.
    const std::string twoVertices = triangleText.substr(0, triangleText.find("pos: -0.7"));
    EXPECT_EQ(errorOf(header(2) + twoVertices + lightText),
              "t.scene:14: error: expected 'pos:' after the triangle's vertex 2 shininess, found "
              "'light' (a triangle has three vertices)");
}

TEST(SceneParserError, KeyGluedToItsNumber) {
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "rad: 1", "rad:1")),
              "t.scene:5: error: the key 'rad:' must be separated from its numbers by whitespace, "
              "found 'rad:1'");
    EXPECT_EQ(errorOf(header(1) + replaced(lightText, "pos: 0", "POS:0")),
              "t.scene:4: error: the key 'pos:' must be separated from its numbers by whitespace, "
              "found 'POS:0'");
    EXPECT_EQ(errorOf("0\namb:0.1 0 0\n"), "t.scene:2: error: the key 'amb:' must be separated "
                                           "from its numbers by whitespace, found 'amb:0.1'");
}

TEST(SceneParserError, NotANumber) {
    for (const char* bad : {"abc", "1.0x", "0x1p3", "1,5", "--1", "+-1", "++1", "+", "-", ".", "e5",
                            "1e", "1..2", "nanx", "1/2"}) {
        EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "rad: 1", "rad: " + std::string(bad))),
                  "t.scene:5: error: expected a number for the sphere's radius, found '" +
                      std::string(bad) + "'");
    }
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "pos: 0.0 0.0 -3.0", "pos: 0.0 0.0")),
              "t.scene:5: error: expected a number for the sphere's position, found 'rad:'");
    EXPECT_EQ(
        errorOf(header(1) + replaced(triangleText, "spe: 0.1 0.2 0.3", "spe: 0.1 0.2 O.3")),
        "t.scene:17: error: expected a number for the triangle's vertex 3 'spe:', found 'O.3'");
    EXPECT_EQ(
        errorOf(header(1) + "light\npos: 0 0 0\ncol: 1 1\n"),
        "t.scene:5: error: expected a number for the light's colour, found the end of the file");
    EXPECT_EQ(
        errorOf(header(1) + replaced(triangleText, "nor: 0 0 1", "nor: 0 0 one")),
        "t.scene:5: error: expected a number for the triangle's vertex 1 normal, found 'one'");
}

TEST(SceneParserError, NonFiniteNumber) {
    for (const char* bad : {"nan", "NaN", "-nan", "+nan", "nan(1)", "inf", "-inf", "+INF",
                            "infinity", "1e999", "-1e309", "1000000e303"}) {
        EXPECT_EQ(errorOf(header(1) +
                          replaced(lightText, "pos: 0 0 0", "pos: 0 " + std::string(bad) + " 0")),
                  "t.scene:4: error: non-finite number '" + std::string(bad) +
                      "' for the light's position");
    }
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "shi: 1", "shi: inf")),
              "t.scene:8: error: non-finite number 'inf' for the sphere's shininess");
}

TEST(SceneParserError, RadiusMustBePositive) {
    for (const char* bad : {"-1", "0", "-0", "0.0", "-1e-400"}) {
        EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "rad: 1", "rad: " + std::string(bad))),
                  "t.scene:5: error: the sphere's radius must be positive, found " +
                      std::string(bad));
    }
}

TEST(SceneParserError, NegativeColorOrShininess) {
    EXPECT_EQ(errorOf(header(1) + replaced(triangleText, "dif: 0 0.5 0", "dif: 0 -0.5 0")),
              "t.scene:11: error: negative colour value -0.5 in the triangle's vertex 2 'dif:'");
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "spe: 0.5 0.5 0.5", "spe: 0.5 0.5\n-1e-9")),
              "t.scene:8: error: negative colour value -1e-9 in the sphere's 'spe:'");
    EXPECT_EQ(errorOf(header(1) + replaced(lightText, "col: 1 1 1", "col: -1 1 1")),
              "t.scene:5: error: negative colour value -1 in the light's colour");
    EXPECT_EQ(errorOf(header(1) + replaced(sphereText, "shi: 1", "shi: -3")),
              "t.scene:8: error: the sphere's shininess must not be negative, found -3");
    EXPECT_EQ(
        errorOf(header(1) + replaced(triangleText, "shi: 30", "shi: -0.5")),
        "t.scene:18: error: the triangle's vertex 3 shininess must not be negative, found -0.5");
    // Negative zero is zero, not negative.
    EXPECT_EQ(parse(header(1) + replaced(sphereText, "shi: 1", "shi: -0")).spheres.size(), 1u);
}

TEST(SceneParserError, FewerObjectsThanTheHeaderSays) {
    EXPECT_EQ(errorOf(header(3) + sphereText + lightText + "\n\n"),
              "t.scene:11: error: the header says 3 objects but the file ends after 2");
    EXPECT_EQ(errorOf("1\namb: 0 0 0\n"),
              "t.scene:2: error: the header says 1 object but the file ends after 0");
}

TEST(SceneParserError, MoreObjectsThanTheHeaderSays) {
    EXPECT_EQ(errorOf(header(1) + sphereText + "\n" + sphereText),
              "t.scene:10: error: the header says 1 object but more follow: 'sphere'");
    EXPECT_EQ(errorOf("0\namb: 0 0 0\n\nlight\n"),
              "t.scene:4: error: the header says 0 objects but more follow: 'light'");
    EXPECT_EQ(errorOf(header(2) + lightText + lightText + "# a comment"),
              "t.scene:9: error: the header says 2 objects but more follow: '#'");
}

TEST(SceneParserError, HugeClaimedCountFailsWithoutAllocating) {
    // Nothing is reserved from the header: this fails at once, with no bad_alloc.
    EXPECT_EQ(errorOf("4000000000\namb: 0 0 0\n"),
              "t.scene:2: error: the header says 4000000000 objects but the file ends after 0");
    EXPECT_EQ(errorOf("18446744073709551615\namb: 0 0 0\n" + lightText),
              "t.scene:5: error: the header says 18446744073709551615 objects but the file ends "
              "after 1");
}

// ------------------------------------------------------------------- files

TEST(SceneLoad, MissingFileOrDirectory) {
    const std::filesystem::path missing =
        std::filesystem::path(testing::TempDir()) / "no_such_dir" / "missing.scene";
    try {
        loadScene(missing);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.line, 0);
        EXPECT_EQ(std::string(e.what()),
                  missing.string() + ": error: cannot open file: No such file or directory");
    }
    const std::filesystem::path directory = testing::TempDir();
    try {
        loadScene(directory);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  directory.string() + ": error: cannot open file: Is a directory");
    }
}

TEST(SceneLoad, UnreadableFile) {
    const std::filesystem::path path =
        std::filesystem::path(testing::TempDir()) / "scene_parser_test_unreadable.scene";
    std::ofstream(path) << header(0);
    std::filesystem::permissions(path, std::filesystem::perms::none);
    const bool readable = std::ifstream(path).is_open(); // root reads anything
    std::string what;
    try {
        loadScene(path);
    } catch (const SceneError& e) {
        what = e.what();
    }
    std::filesystem::remove(path);
    if (readable) GTEST_SKIP() << "running with permission to read any file";
    EXPECT_EQ(what, path.string() + ": error: cannot open file: Permission denied");
}

TEST(SceneLoad, ReadsBytesAsTheyAreAndNamesThePath) {
    const std::filesystem::path path =
        std::filesystem::path(testing::TempDir()) / "scene_parser_test_crlf.scene";
    {
        std::ofstream out(path, std::ios::binary);
        out << "\xEF\xBB\xBF"
               "1\r\namb: 0 0 0\r\nlight\r\npos: 1 2 3\r\ncol: 1 1 1\r\nextra\r\n";
    }
    try {
        loadScene(path);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path.string() + ":6: error: the header says 1 object but more follow: 'extra'");
    }
    {
        std::ofstream out(path, std::ios::binary);
        out << std::string("1\r\n\0", 4);
    }
    try {
        loadScene(path);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path.string() + ": error: the file is binary (NUL byte at offset 3)");
    }
    std::filesystem::remove(path);
}

struct Counts {
    size_t spheres, triangles, lights;
};

TEST(SceneLoad, EverySharedSampleSceneLoads) {
    const std::filesystem::path dir = SHARED_SCENES_DIR;
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << dir << " is absent";
    const std::map<std::string, Counts> expected = {
        {"test1.scene", {1, 0, 1}},    {"test1-b.scene", {1, 0, 1}},
        {"test1-c.scene", {1, 0, 1}},  {"test2.scene", {1, 3, 1}},
        {"test2-b.scene", {1, 3, 1}},  {"spheres.scene", {5, 2, 1}},
        {"table.scene", {0, 182, 2}},  {"SIGGRAPH.scene", {0, 1482, 3}},
        {"snow.scene", {7, 490, 3}},   {"toy.scene", {0, 569, 3}},
        {"screenfile.txt", {1, 0, 1}}, {"screenfile-b.txt", {1, 0, 1}},
    };
    size_t loaded = 0, checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        SCOPED_TRACE(entry.path().string());
        Scene scene;
        ASSERT_NO_THROW(scene = loadScene(entry.path()));
        ++loaded;
        EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front(); // no odd values in them
        const auto it = expected.find(entry.path().filename().string());
        if (it == expected.end()) continue;
        ++checked;
        EXPECT_EQ(scene.spheres.size(), it->second.spheres);
        EXPECT_EQ(scene.triangles.size(), it->second.triangles);
        EXPECT_EQ(scene.lights.size(), it->second.lights);
    }
    EXPECT_GE(loaded, 12u);
    EXPECT_EQ(checked, expected.size());
}

TEST(SceneLoad, EveryProjectSceneLoads) {
    const std::filesystem::path dir = PROJECT_SCENES_DIR;
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << dir << " is absent";
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".scene") continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW(loadScene(entry.path()));
    }
}

TEST(SceneParser, LargeInputParsesQuickly) {
    // 200k triangles, about 44 MB: the size of the largest scenes we expect.
    constexpr int count = 200000;
    std::string text =
        std::to_string(count + 1) + "\namb: 0.1 0.1 0.1\nlight\npos: 0 5 0\ncol: 1 1 1\n";
    text.reserve(210u * count);
    const auto depth = [](int i) {
        return std::to_string(-1 - i % 1000) + "." + std::to_string(i % 97);
    };
    for (int i = 0; i < count; ++i) {
        const std::string z = depth(i);
        text += "triangle\n";
        for (const char* xy : {"-1.25 0", "1.5 0", "0 1.0625"})
            text += std::string("pos: ") + xy + " " + z +
                    "\nnor: 0 0 1\ndif: 0.5 0.25 0.125\nspe: 0 0 0\nshi: 10\n";
    }
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = parse(text);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("parsed %.1f MB, %d triangles in %.0f ms\n", text.size() / 1e6, count, ms);
    ASSERT_EQ(scene.triangles.size(), static_cast<size_t>(count));
    EXPECT_EQ(scene.triangles.back().vertices[2].position,
              glm::dvec3(0, 1.0625, std::stod(depth(count - 1))));
    EXPECT_TRUE(scene.warnings.empty());
}

// ------------------------------------------------------- numbers, fast and slow

// The one-pass decimal reader must give exactly what from_chars gives, bit for bit,
// and the same verdict, on every form: short and long mantissas, points anywhere,
// exponents around the exact range of powers of ten, mantissas around 2^53.
TEST(SceneNumbers, FastPathMatchesFromCharsBitForBit) {
    std::mt19937_64 random(12345);
    const auto check = [](const std::string& token) {
        double fast = 0.0, slow = 0.0;
        const scene_lexer::NumberStatus fastStatus = scene_lexer::parseNumber(token, fast);
        const scene_lexer::NumberStatus slowStatus = scene_lexer::parseNumberSlow(token, slow);
        ASSERT_EQ(fastStatus, slowStatus) << token;
        if (fastStatus == scene_lexer::NumberStatus::ok) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(fast), std::bit_cast<std::uint64_t>(slow))
                << token;
        }
    };
    for (const char* token : {"0",
                              "-0",
                              "+0",
                              "0.0",
                              "-0.0",
                              "00",
                              ".0",
                              "0.",
                              "1",
                              "-1",
                              "+1",
                              "9007199254740992",
                              "9007199254740993",
                              "9007199254740991",
                              "-9007199254740993",
                              "18446744073709551615",
                              "18446744073709551616",
                              "9999999999999999999",
                              "99999999999999999999",
                              "1e22",
                              "1e23",
                              "1e-22",
                              "1e-23",
                              "9007199254740992e22",
                              "9007199254740993e-22",
                              "123456789e-30",
                              "0.000000000000000000001",
                              "1.5e+0",
                              "1.5E-0",
                              "2.2250738585072014e-308",
                              "4.9e-324",
                              "1e-400",
                              "1e400",
                              "0e999",
                              "-0e-999",
                              "1.e5",
                              ".5e1",
                              "5.e-1",
                              "-.5",
                              "+.5",
                              "1e",
                              "1e+",
                              "e1",
                              ".",
                              "-",
                              "+",
                              "+-1",
                              "--1",
                              "1.2.3",
                              "1e1.5",
                              "0x10",
                              "inf",
                              "nan",
                              "1,5",
                              "１",
                              "0.1",
                              "0.2",
                              "0.3",
                              "-2.6748e-08",
                              "0.4699999988079071",
                              "-0.35315093486933696",
                              "1.44076172",
                              "-12",
                              "0.75"})
        check(token);
    std::uniform_int_distribution<int> digitCount(1, 24), digit(0, 9), exponent(-40, 40),
        coin(0, 3);
    for (int i = 0; i < 200000; ++i) {
        std::string token = coin(random) == 0 ? "-" : coin(random) == 0 ? "+" : "";
        const int digits = digitCount(random);
        const int point = std::uniform_int_distribution<int>(-1, digits)(random);
        for (int d = 0; d < digits; ++d) {
            if (d == point) token += '.';
            token += char('0' + digit(random));
        }
        if (point == digits) token += '.';
        if (coin(random) != 0) {
            token += coin(random) == 0 ? 'E' : 'e';
            const int e = exponent(random);
            token += e < 0 ? "-" : coin(random) == 0 ? "+" : "";
            token += std::to_string(std::abs(e));
        }
        check(token);
        if (HasFatalFailure()) return;
    }
    // The numbers that scene generators write: %.9g and %.17g of random doubles.
    std::uniform_real_distribution<double> value(-1000.0, 1000.0);
    for (int i = 0; i < 100000; ++i) {
        char text[64];
        const double x = value(random) * std::pow(10.0, exponent(random) / 4);
        std::snprintf(text, sizeof text, i % 2 ? "%.9g" : "%.17g", x);
        check(text);
        if (HasFatalFailure()) return;
    }
}

// ------------------------------------------------------------ binary check

// The sixteen- and eight-bytes-at-a-time scans must flag exactly what the byte-by-byte
// rule flags, at every offset within and across blocks.
TEST(SceneText, BinaryCheckFindsEveryByteAtEveryOffset) {
    for (int byte = 0; byte < 256; ++byte) {
        const char c = char(byte);
        const bool text = (byte >= 0x20 && byte < 0x7F) || scene_lexer::isSpace(c);
        for (std::size_t at = 0; at < 44; ++at) {
            std::string sample(44, 'a');
            sample[at] = c;
            const auto reason = scene_lexer::binaryReason(sample);
            std::string expected;
            if (byte == 0)
                expected = "NUL byte at offset " + std::to_string(at);
            else if (byte < 0x80 && !text)
                expected = "control byte 0x";
            else if (byte >= 0x80)
                expected = "invalid UTF-8 at offset " + std::to_string(at); // a lone lead byte
            if (text) {
                EXPECT_FALSE(reason.has_value()) << byte << " at " << at;
            } else {
                ASSERT_TRUE(reason.has_value()) << byte << " at " << at;
                EXPECT_EQ(reason->substr(0, expected.size()), expected);
                EXPECT_NE(reason->find("offset " + std::to_string(at)), std::string::npos);
            }
        }
    }
    // Multi-byte characters across a word boundary are text.
    for (std::size_t at = 0; at < 12; ++at)
        EXPECT_FALSE(scene_lexer::binaryReason(std::string(at, 'a') +
                                               "\xC3\xA8\xE2\x82\xAC\xF0\x9F\x98\x80" +
                                               std::string(9, 'b'))
                         .has_value());
}

// ------------------------------------------------------ reading in parallel

// A scene of many small objects with warnings, blank lines and mixed line ends, so that
// chunks start at every kind of object and warnings fall in every chunk.
std::string mixedScene(int groups) {
    std::string objects;
    for (int i = 0; i < groups; ++i) {
        objects += replaced(sphereText, "rad: 1", "rad: " + std::to_string(i + 1));
        objects +=
            i % 3 == 0 ? replaced(triangleText, "dif: 0 0 0.5", "dif: 0 0 1.5") : triangleText;
        objects += i % 4 == 1 ? "\r\n\r\n" : "\n";
        objects += i % 5 == 2 ? lightText : "LIGHT\npos: 1 1 1\ncol: 1 1 1\n";
    }
    return header(3 * groups) + objects;
}

// What parsing gives, as one string: the error, or every value (hex floats) and warning.
std::string outcome(std::string_view text, const SceneParseOptions& options) {
    Scene scene;
    try {
        scene = parseScene(text, "t.scene", options);
    } catch (const SceneError& e) {
        return e.what();
    }
    std::ostringstream out;
    out << std::hexfloat;
    const auto material = [&](const Material& m) {
        out << m.diffuse.x << m.diffuse.y << m.diffuse.z << m.specular.x << m.specular.y
            << m.specular.z << m.shininess << ';';
    };
    out << scene.ambient.x << scene.ambient.y << scene.ambient.z << '\n';
    for (const Sphere& s : scene.spheres) {
        out << "S@" << s.line << s.center.x << s.center.y << s.center.z << s.radius;
        material(s.material);
    }
    for (const Triangle& t : scene.triangles)
        for (const Vertex& v : t.vertices) {
            out << "@" << t.line;
            out << "V" << v.position.x << v.position.y << v.position.z << v.normal.x << v.normal.y
                << v.normal.z;
            material(v.material);
        }
    for (const Light& l : scene.lights)
        out << "L@" << l.line << l.position.x << l.position.y << l.position.z << l.color.x
            << l.color.y << l.color.z;
    for (const std::string& warning : scene.warnings)
        out << '\n' << warning;
    return out.str();
}

std::string inOnePass(std::string_view text) {
    return outcome(text, {1, 1});
}

// Several thread counts, with chunks as small as one byte so that even a short text is
// split, each at other places.
void expectSameAsOnePass(std::string_view text) {
    const std::string expected = inOnePass(text);
    for (unsigned threads : {2u, 3u, 5u})
        ASSERT_EQ(outcome(text, {threads, 1}), expected) << threads << " threads";
}

// A file of several megabytes is mapped rather than read (host/scene/mapped_file.h) and
// split among threads: it must load exactly as its text parses in one pass, errors and
// their line numbers included.
TEST(SceneLoad, LargeFileLoadsAsItsTextParses) {
    const std::filesystem::path path =
        std::filesystem::path(testing::TempDir()) / "scene_parser_test_large.scene";
    const std::string text = mixedScene(14000); // about 4 MB
    ASSERT_GT(text.size(), 3u << 20);
    std::string damaged = text;
    damaged.replace(damaged.rfind("rad: "), 5, "rod: ");
    for (const std::string& content : {text, damaged}) {
        std::ofstream(path, std::ios::binary) << content;
        std::string loaded;
        try {
            const Scene scene = loadScene(path);
            loaded = std::to_string(scene.triangles.size()) + " triangles, " +
                     std::to_string(scene.warnings.size()) + " warnings, the last " +
                     scene.warnings.back();
        } catch (const SceneError& e) {
            loaded = e.what();
        }
        std::string parsed;
        try {
            const Scene scene = parseScene(content, path.string(), {1, 1});
            parsed = std::to_string(scene.triangles.size()) + " triangles, " +
                     std::to_string(scene.warnings.size()) + " warnings, the last " +
                     scene.warnings.back();
        } catch (const SceneError& e) {
            parsed = e.what();
        }
        EXPECT_EQ(loaded, parsed);
    }
    std::filesystem::remove(path);
}

TEST(SceneParallel, ChunksStartAtObjectKeywords) {
    const std::string text = mixedScene(20);
    for (unsigned threads = 1; threads <= 8; ++threads) {
        const std::vector<std::size_t> starts = scene_lexer::chunkStarts(text, threads, 1);
        EXPECT_EQ(starts.size(), threads); // every share of this text holds a keyword
        EXPECT_EQ(starts.front(), 0u);
        for (std::size_t k = 1; k < starts.size(); ++k) {
            EXPECT_GT(starts[k], starts[k - 1]);
            EXPECT_TRUE(scene_lexer::isSpace(text[starts[k] - 1]));
            const std::string_view word = std::string_view(text).substr(starts[k], 5);
            EXPECT_TRUE(word == "spher" || word == "trian" || word == "LIGHT" || word == "light")
                << word;
        }
    }
    EXPECT_EQ(scene_lexer::chunkStarts(text, 8, text.size()).size(), 1u); // too small to split
    EXPECT_EQ(scene_lexer::chunkStarts(std::string(100, 'x'), 4, 1).size(), 1u); // no keyword
}

TEST(SceneParallel, ValidSceneIsTheSameAsInOnePass) {
    const std::string text = mixedScene(30);
    ASSERT_EQ(inOnePass(text).find("error"), std::string::npos) << inOnePass(text);
    ASSERT_NE(inOnePass(text).find(":"), std::string::npos); // it has warnings, with lines
    expectSameAsOnePass(text);
    expectSameAsOnePass("\xEF\xBB\xBF" + text);
    expectSameAsOnePass(text + "\n\n\n");
}

TEST(SceneParallel, ObjectCountThatDoesNotAddUp) {
    const std::string objects = mixedScene(20).substr(header(60).size());
    for (int count : {0, 1, 30, 59, 61, 100})
        expectSameAsOnePass(header(count) + objects);
    expectSameAsOnePass(header(60) + objects + "sphere\n"); // more follow, in the last chunk
    expectSameAsOnePass(header(60) + objects.substr(0, objects.size() - 20)); // cut short
}

// The first error in file order wins, wherever the chunks begin: one planted early and
// one planted late give the early one; the late one alone is reported with its line.
TEST(SceneParallel, FirstErrorInFileOrderWins) {
    const std::string text = mixedScene(20);
    const std::size_t early = text.find("rad: 3"), late = text.rfind("shi: 40");
    std::string both = text;
    both.replace(late, 7, "shi: -4");
    both.replace(early, 6, "rad: 0");
    const std::string expected =
        "t.scene:" +
        std::to_string(1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(early), '\n')) +
        ": error: the sphere's radius must be positive, found 0";
    for (unsigned threads = 1; threads <= 7; ++threads)
        EXPECT_EQ(outcome(both, {threads, 1}), expected) << threads;
    std::string lateOnly = text;
    lateOnly.replace(late, 7, "shi: -4");
    ASSERT_NE(inOnePass(lateOnly).find("shininess must not be negative, found -4"),
              std::string::npos);
    expectSameAsOnePass(lateOnly);
}

// Every single-token damage anywhere in the file reads the same as in one pass:
// deleted, replaced by a word, a bad number, an object keyword, or doubled.
TEST(SceneParallel, EveryDamagedTokenIsReportedAsInOnePass) {
    const std::string text = mixedScene(8);
    std::vector<std::pair<std::size_t, std::size_t>> tokens; // offset, length
    for (scene_lexer::Tokenizer tokenizer{text};;) {
        const scene_lexer::Token token = tokenizer.next();
        if (token.text.empty()) break;
        tokens.emplace_back(std::size_t(token.text.data() - text.data()), token.text.size());
    }
    const char* replacements[] = {"", "x", "-1", "nan", "sphere", "TRIANGLE", "light"};
    for (std::size_t i = 0; i < tokens.size(); i += 3) {
        const auto [at, length] = tokens[i];
        for (const char* replacement : replacements) {
            std::string damaged = text;
            damaged.replace(at, length, replacement);
            expectSameAsOnePass(damaged);
            if (HasFatalFailure()) return;
        }
        std::string doubled = text;
        doubled.insert(at, text.substr(at, length) + " ");
        expectSameAsOnePass(doubled);
        if (HasFatalFailure()) return;
    }
}

// Two damaged tokens, one in each half: always the first one's error.
TEST(SceneParallel, TwoDamagedTokensGiveTheFirstError) {
    const std::string text = mixedScene(12);
    std::mt19937 random(7);
    std::uniform_int_distribution<std::size_t> firstHalf(0, text.size() / 2 - 1),
        secondHalf(text.size() / 2, text.size() - 1);
    for (int i = 0; i < 200; ++i) {
        std::string damaged = text;
        damaged[secondHalf(random)] = '?';
        damaged[firstHalf(random)] = '#';
        expectSameAsOnePass(damaged);
        if (HasFatalFailure()) return;
    }
}

// A large generated mesh file, split among threads as a user's file would be, reads
// exactly as in one pass.
TEST(SceneParallel, LargeSceneIsTheSameInChunks) {
    std::string text = header(3 * 3000);
    std::string objects;
    for (int i = 0; i < 3000; ++i) {
        text += replaced(sphereText, "0.0 0.0 -3.0", std::to_string(i) + ".25 0.5 -3");
        text += replaced(triangleText, "-1.2 0 -2", "-1.2 " + std::to_string(i) + " -2");
        text += lightText;
    }
    const std::string expected = inOnePass(text);
    ASSERT_EQ(expected.find("error"), std::string::npos);
    for (unsigned threads : {2u, 3u, 8u})
        EXPECT_EQ(outcome(text, {threads, 4096}), expected);
    EXPECT_EQ(outcome(text, {}), expected); // the defaults
}

} // namespace

namespace {

// count triangles, each with a zero normal at vertex (1 + i % 3) and, every fourth one,
// zero area too: two kinds of warning, interleaved.
std::string zeroNormalTriangles(int count) {
    std::string text = std::to_string(count) + "\namb: 0 0 0\n";
    const std::string material = "dif: 0.5 0.5 0.5\nspe: 0 0 0\nshi: 1\n";
    for (int i = 0; i < count; ++i) {
        const bool flat = i % 4 == 0;
        text += "triangle\n";
        for (int v = 0; v < 3; ++v)
            text += "pos: " + std::to_string(flat ? 0 : v) + " " + std::to_string(v == 2) +
                    " -1\nnor: " + (v == i % 3 ? "0 0 0" : "0 0 1") + "\n" + material;
    }
    return text;
}

} // namespace

TEST(SceneWarnings, KindIsTheMessageWithItsNumbersWrittenN) {
    EXPECT_EQ(warningKind("a.scene:17: warning: the triangle's vertex 2 normal has zero length"),
              "the triangle's vertex N normal has zero length");
    EXPECT_EQ(warningKind("x:y.scene:3: warning: the sphere's diffuse colour 1.5e+2 is above 1; "
                          "used as given"),
              "the sphere's diffuse colour N is above N; used as given");
    EXPECT_EQ(warningKind("a.scene:1: warning: the triangle has zero area (its vertices are "
                          "collinear or coincide)"),
              "the triangle has zero area (its vertices are collinear or coincide)");
}

// 35,005 zero normals and 8,752 flat triangles: the first 20 of each, in file order, then
// one line for each kind's rest. Counts and the lines kept come from the text as generated.
TEST(SceneWarnings, BeyondTwentyOfAKindOneLineSaysHowManyMore) {
    const int count = 35005;
    const Scene scene = parseScene(zeroNormalTriangles(count), "mesh.scene");
    const int flat = (count + 3) / 4;
    ASSERT_EQ(scene.warnings.size(), std::size_t(count + flat));
    const std::vector<std::string> lines = summarisedWarnings(scene.warnings);
    ASSERT_EQ(lines.size(), 20u + 20u + 2u);
    std::vector<std::string> expected;
    int normals = 0, flats = 0;
    for (const std::string& warning : scene.warnings) {
        int& seen = warning.find("zero length") != std::string::npos ? normals : flats;
        if (seen++ < 20) expected.push_back(warning);
    }
    expected.push_back("mesh.scene: warning: ... and 34,985 more warnings that the triangle's "
                       "vertex N normal has zero length");
    expected.push_back("mesh.scene: warning: ... and 8,732 more warnings that the triangle has "
                       "zero area (its vertices are collinear or coincide)");
    EXPECT_EQ(lines, expected);
    // Up to twenty of a kind, every warning is printed as it is.
    const Scene few = parseScene(zeroNormalTriangles(20), "few.scene");
    EXPECT_EQ(summarisedWarnings(few.warnings), few.warnings);
}
