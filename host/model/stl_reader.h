// STL models (binary, and ASCII `solid ... facet ... vertex x y z ... endsolid`) to the
// SourceModel an OBJ file becomes, read here rather than through assimp (docs/models.md says
// why). STL repeats a position at every corner: corners at the same position, bit for bit,
// become one position, as an OBJ file's shared `v` would be, so that smooth normals join
// them. Its facet normals are not used: the crease rule gives the model its normals, as
// for an OBJ file without `vn`. STL has no materials: every face gets the default one.
#pragma once

#include "model/source_model.h"

#include <string>
#include <string_view>

// Throws SceneError naming fileName (and, in ASCII, the line) for a binary file whose size
// is not its header's triangle count times 50 plus 84, a malformed vertex line, a file cut
// short inside a facet, or a model without triangles.
SourceModel readStl(std::string_view bytes, const std::string& fileName);
