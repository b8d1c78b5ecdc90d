// PLY models (ASCII, binary little- and big-endian) to the SourceModel an OBJ file becomes,
// read here rather than through assimp (docs/models.md says why): the vertex element's
// x, y, z, its nx, ny, nz when all three are there, its red, green, blue (integers over
// their type's largest value, floats as they are); the face element's vertex_indices (or
// vertex_index) as polygons; a tristrips element's strips (-1 restarts a strip) as
// triangles, alternating their winding as strips do, the joins' degenerate triangles left
// out. Every other element and property is skipped by its size. Counts the header claims
// are checked against the bytes after it before anything is allocated for them.
#pragma once

#include "model/source_model.h"

#include <string>
#include <string_view>

// Throws SceneError naming fileName (and, in ASCII, the line) for a malformed header, a
// file cut short, an index out of range, or a model without faces.
SourceModel readPly(std::string_view bytes, const std::string& fileName);
