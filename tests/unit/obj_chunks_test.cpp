// The OBJ reader on all threads (host/model/obj_survey.h, obj_fill.h): chunks start only
// where a statement starts, and a text read in chunks gives the model, the warnings and
// the first error of one pass, whichever chunk or step (a chunk's statement, a library
// read in the replay) meets it. obj_fuzz_replay holds every fuzz input to the same.
#include "model/obj_reader.h"
#include "model/obj_survey.h"
#include "scene/scene_error.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace {

// A library named bad.mtl cannot be read; every other one is missing.
MtlFile lookUp(const std::string& name) {
    if (name == "bad.mtl") throw SceneError("bad.mtl", 0, "not a regular file");
    if (name == "red.mtl") return MtlFile{name, "newmtl red\nKd 1 0 0\n"};
    return MtlFile{name, std::nullopt};
}

// The model in words, or its error: what one pass and every split must agree on.
std::string outcome(const std::string& text, unsigned chunks) {
    try {
        const SourceModel model = parseObj(text, "m.obj", lookUp, ObjParseOptions{chunks, 1});
        std::string words = std::to_string(model.positions.size()) + " positions, " +
                            std::to_string(model.triangles.size()) + " triangles;";
        for (std::size_t t = 0; t < model.triangles.size(); ++t)
            words += " " + std::to_string(model.triangles.positions(t)[2]) + "@" +
                     std::to_string(model.triangles.line(t)) + "m" +
                     std::to_string(model.triangles.material(t));
        words += model.triangles.facesAreTriangles() ? "\nfaces: the triangles" : "\nfaces:";
        for (std::size_t f = 0; f < faceCount(model); ++f) {
            words += " ";
            for (const std::uint32_t p : facePositions(model, f))
                words += std::to_string(p) + ",";
        }
        for (const std::string& warning : model.warnings)
            words += "\n" + warning;
        return words;
    } catch (const SceneError& error) {
        return error.what();
    }
}

// A text of `faces` triangles, a v line and an f line each after two shared positions, with
// the line `extra` put in as line `at` (none at 0).
std::string triangles(int faces, int at = 0, const std::string& extra = "") {
    std::vector<std::string> lines{"v 0 0 0", "v 1 0 0"};
    for (int i = 0; i < faces; ++i) {
        lines.push_back("v " + std::to_string(i) + " 1 0");
        lines.push_back("f 1 2 -1");
    }
    if (at > 0) lines.insert(lines.begin() + (at - 1), extra);
    std::string text;
    for (const std::string& line : lines)
        text += line + "\n";
    return text;
}

TEST(ObjChunks, ChunksStartAfterALineThatIsNotContinued) {
    // Every line but the last of each pair continues on the next: LF, CRLF and CR.
    const std::string text = "v 1 \\\n2 3\nv 1 \\\r\n2 3\r\nv 1 \\\r2 3\rf 1 2 3\n";
    for (unsigned chunks = 2; chunks <= 8; ++chunks)
        for (const std::size_t start : objChunkStarts(text, chunks, 1)) {
            if (start == 0) continue;
            ASSERT_EQ(text[start - 1], '\n') << start;
            const std::size_t end = text[start - 2] == '\r' ? start - 2 : start - 1;
            EXPECT_NE(text[end - 1], '\\') << "chunk at " << start << " of " << chunks;
        }
}

TEST(ObjChunks, AnyChunkCountGivesTheModelAndWarningsOfOnePass) {
    const std::string text = "mtllib red.mtl missing.mtl\n" + triangles(40, 30, "usemtl red") +
                             "usemtl nothing\nf 1 2 3\nl 1 2\nf 1 2 3 4\n";
    const std::string whole = outcome(text, 1);
    EXPECT_NE(whole.find("42 positions, 43 triangles"), std::string::npos) << whole;
    EXPECT_NE(whole.find("m.obj:1: warning: material library missing.mtl not found; 2 of 42"),
              std::string::npos)
        << whole;
    for (unsigned chunks = 2; chunks <= 9; ++chunks)
        EXPECT_EQ(outcome(text, chunks), whole) << chunks << " chunks";
}

TEST(ObjChunks, TheFirstErrorInFileOrderWinsWhereverItIs) {
    // A face out of range late in the text, a library that cannot be read early, and the
    // other way round; and two errors in statements, far apart.
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"mtllib bad.mtl\n" + triangles(30, 50, "f 1 2 999"), "bad.mtl: error: not a regular"},
        {triangles(30, 5, "f 1 2 999") + "mtllib bad.mtl\n", "m.obj:5: error: vertex index 999"},
        {triangles(30, 7, "v 1 2") + "f 0 1 2\n", "m.obj:7: error: v expects 3"},
        {triangles(30, 57, "vn 1 2 x"), "m.obj:57: error: vn: 'x' is not a number"},
        // As many corners as triangles would have, but in a face of two and one of four.
        {triangles(30, 9, "f 1 2") + "f 1 2 3 4\n", "m.obj:9: error: a face needs at least 3"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string whole = outcome(text, 1);
        EXPECT_NE(whole.find(expected), std::string::npos) << whole;
        for (unsigned chunks = 2; chunks <= 9; ++chunks)
            EXPECT_EQ(outcome(text, chunks), whole) << chunks << " chunks";
    }
}

TEST(ObjChunks, IndicesCountBackAcrossChunks) {
    // Each face's -1 is the position on the line before it, in whatever chunk that is.
    const std::string text = triangles(60);
    const std::string whole = outcome(text, 1);
    EXPECT_NE(whole.find(" 61@122m0"), std::string::npos) << whole;
    for (unsigned chunks = 2; chunks <= 9; ++chunks)
        EXPECT_EQ(outcome(text, chunks), whole) << chunks << " chunks";
}

TEST(ObjChunks, FacesOfThreeCornersAreTheirTrianglesInEveryChunk) {
    // Every face a triangle: the model keeps no face arrays, and face f is triangle f (the
    // face list above is read through them). One quad anywhere, and the faces are kept.
    const std::string text = triangles(60);
    const SourceModel model = parseObj(text, "m.obj", lookUp, ObjParseOptions{4, 1});
    EXPECT_TRUE(model.triangles.facesAreTriangles());
    EXPECT_TRUE(model.facePositions.empty());
    EXPECT_EQ(model.faceStarts.size(), 1u);
    ASSERT_EQ(faceCount(model), 60u);
    for (std::size_t f = 0; f < 60; ++f) {
        const std::span<const std::uint32_t> corners = facePositions(model, f);
        ASSERT_EQ(corners.size(), 3u);
        EXPECT_EQ(corners[2], f + 2) << f;
        EXPECT_EQ(model.triangles.face(f), f);
    }
    const std::string whole = outcome(text, 1);
    EXPECT_NE(whole.find("\nfaces: the triangles 0,1,2, 0,1,3,"), std::string::npos) << whole;
    for (unsigned chunks = 2; chunks <= 9; ++chunks)
        EXPECT_EQ(outcome(text, chunks), whole) << chunks << " chunks";

    const std::string withQuad = triangles(60, 70, "f 1 2 3 4");
    const std::string kept = outcome(withQuad, 1);
    EXPECT_NE(kept.find("\nfaces: 0,1,2, 0,1,3,"), std::string::npos) << kept;
    EXPECT_NE(kept.find(" 0,1,2,3, "), std::string::npos) << kept;
    for (unsigned chunks = 2; chunks <= 9; ++chunks)
        EXPECT_EQ(outcome(withQuad, chunks), kept) << chunks << " chunks";
}

TEST(ObjChunks, TheSurveyCountsAFacesWordsAsThePlainDefinitionDoes) {
    // Lines of every length around the sixteen bytes the survey reads at once, of words,
    // each whitespace byte, '#' anywhere and bytes above 127; each a face whose corners
    // are the words after "f" before any '#'.
    std::mt19937 random(7);
    const std::string alphabet = std::string(" \t\v\f\r#1/a") + char(0x80) + char(0xFF) + "  11";
    for (int round = 0; round < 3000; ++round) {
        std::string line = "f ";
        const int length = int(random() % 70);
        for (int i = 0; i < length; ++i)
            line += alphabet[random() % alphabet.size()];
        std::size_t words = 0;
        bool inWord = false;
        for (const char c : line) {
            if (c == '#') break;
            const bool space = c == ' ' || (c >= '\t' && c <= '\r');
            words += !space && !inWord;
            inWord = !space;
        }
        if (line.find('\r') != std::string::npos) continue; // a line end of its own
        const ObjChunkSurvey survey = surveyObjChunk(line + "\n", nullptr);
        ASSERT_EQ(survey.faces, 1u) << line;
        EXPECT_EQ(survey.facePositions, words - 1) << '"' << line << '"';
    }
}

} // namespace
