// The OBJ reader's first pass over each chunk of a file, all chunks at once (obj_reader.h):
// how many positions, normals, texture coordinates, faces and triangles the chunk's
// statements make, so that the second pass writes each chunk straight into the model's
// arrays at its own place; and, in order, the statements whose effect crosses chunks
// (mtllib, usemtl) and the keywords the reader ignores, which the reader then replays in
// file order. The counts are exact for a chunk the second pass reads without an error.
#pragma once

#include "base/phase_progress.h"
#include "scene/scene_lexer.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// What an OBJ statement's keyword makes the reader do.
enum class ObjKeyword { position, normal, texcoord, face, mtllib, usemtl, skipped, ignored };
ObjKeyword objKeyword(std::string_view keyword);

// The keyword of the common lines, "v ", "vn ", "vt " and "f " (any space after), found from
// their first characters without splitting them; none for any other line, whose keyword
// splitStatement finds. Both passes read a line's kind so, and so count the same. Inline: a
// call returning the optional through memory stalled on every line of a large file.
inline std::optional<ObjKeyword> leadingKeyword(std::string_view line) {
    using scene_lexer::isSpace;
    if (line.size() >= 2 && isSpace(line[1])) {
        if (line[0] == 'v') return ObjKeyword::position;
        if (line[0] == 'f') return ObjKeyword::face;
    }
    if (line.size() >= 3 && line[0] == 'v' && isSpace(line[2])) {
        if (line[1] == 'n') return ObjKeyword::normal;
        if (line[1] == 't') return ObjKeyword::texcoord;
    }
    return std::nullopt;
}

struct ObjEvent {
    ObjKeyword kind = ObjKeyword::usemtl; // mtllib, usemtl or ignored
    int line = 0;                         // the chunk's, from 1
    std::size_t facesBefore = 0;          // the chunk's faces before it
    // mtllib: the libraries' names; usemtl: the material's name; ignored: the keyword.
    std::vector<std::string> words;
};

struct ObjChunkSurvey {
    int lines = 0; // physical lines
    std::size_t positions = 0, normals = 0, texcoords = 0;
    std::size_t faces = 0, facePositions = 0, triangles = 0;
    std::size_t polygons = 0;     // faces of other than three corners
    std::vector<ObjEvent> events; // an ignored keyword only where the chunk first has it
};

// Where each of up to `most` chunks of text starts (0: kObjChunksPerThread a thread of
// workerThreads(), base/parallel.h): 0, then at each further equal share the start of the
// next line that begins a statement (the line before it does not end in a backslash). No
// chunk is shorter than minChunkBytes. Several chunks a thread, handed out in turn, keep the
// threads busy to the end where one part of a file is slower to read than another (faces
// than positions).
constexpr unsigned kObjChunksPerThread = 8;
std::vector<std::size_t> objChunkStarts(std::string_view text, unsigned most,
                                        std::size_t minChunkBytes);

// progress (none: nullptr) is advanced by the chunk's bytes as they are read.
ObjChunkSurvey surveyObjChunk(std::string_view chunk, PhaseProgress* progress = nullptr);
