// The OBJ reader's second pass over each chunk of a file, all chunks at once
// (obj_reader.h): the chunk's statements read into the model's arrays, sized beforehand
// from every chunk's survey (obj_survey.h), at the chunk's own place in them. Polygons are
// split into triangles after every chunk is read (splitObjPolygons), since their corners
// may be positions of a chunk still being read.
#pragma once

#include "base/phase_progress.h"
#include "model/source_model.h"
#include "scene/scene_error.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

// Where a chunk's statements go: the first line, position, normal, ... of the chunk in
// the file and the model, and its one past the last (the chunk's survey added).
struct ObjChunkPlace {
    int firstLine = 1;
    std::size_t positions = 0, normals = 0, texcoords = 0;
    std::size_t faces = 0, facePositions = 0, triangles = 0;
};

// A face of more than three corners, split once every position is read.
struct ObjPolygon {
    std::size_t firstTriangle = 0; // its corners - 2 triangles' place in model.triangles
    std::uint32_t face = 0, material = 0;
    int line = 0;
    std::size_t firstCorner = 0, corners = 0; // in ObjChunkResult::polygonCorners
};

struct ObjChunkResult {
    std::optional<SceneError> error; // the chunk's first; it stops there
    std::vector<ObjPolygon> polygons;
    std::vector<SourceCorner> polygonCorners;
    // The chunk's positions that have a colour (index, colour): the model's colors are made
    // from them, and only when some position has one.
    std::vector<std::pair<std::uint32_t, glm::dvec3>> colors;
};

// The materials each usemtl gives, in the chunk's order, and the one before its first.
struct ObjChunkMaterials {
    std::uint32_t atStart = 0;
    std::vector<std::uint32_t> usemtl;
};

// Reads chunk (the file's text from place.firstLine on) into model's arrays at place, up to
// end; mtllib and the ignored statements are left to the reader's replay of them.
ObjChunkResult fillObjChunk(std::string_view chunk, const std::string& fileName,
                            const ObjChunkPlace& place, const ObjChunkPlace& end,
                            const ObjChunkMaterials& materials, SourceModel& model,
                            PhaseProgress* progress = nullptr);

// Splits the chunk's polygons into their triangles in model; the number split as fans
// although concave (polygon_triangulation.h), and the line of the first of them.
struct FannedConcave {
    std::size_t count = 0;
    int firstLine = 0;
};
FannedConcave splitObjPolygons(const ObjChunkResult& chunk, SourceModel& model);
