// Wavefront OBJ text (and the MTL files it names) to a SourceModel. The rules, which
// tools/obj_to_scene.py follows too, are in docs/models.md: faces of 3 or more corners
// (v, v/vt, v/vt/vn, v//vn; 1-based or negative indices), split into triangles
// (polygon_triangulation.h: a fan when convex, ear clipping when concave); vn as given; `v x y z r
// g b` colours; Kd, Ks and Ns of newmtl materials. Texture coordinates, groups and smoothing groups
// are read and ignored. A malformed line is a SceneError "FILE:LINE: error: ..."; a binary file is
// not an OBJ file.
#pragma once

#include "model/source_model.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

// A material library, looked up by the name an mtllib line gives: the path it has in
// messages, and its text, or no text when there is no such file.
struct MtlFile {
    std::string path;
    std::optional<std::string> text;
};
using MtlLookup = std::function<MtlFile(const std::string& name)>;

// fileName is used in messages; lookUpMtl finds the libraries that mtllib names.
SourceModel parseObj(std::string_view text, const std::string& fileName,
                     const MtlLookup& lookUpMtl);

// The model in text, the file at path (whose name is used in messages), with the
// libraries beside it that it names.
SourceModel readObjFile(const std::filesystem::path& path, std::string_view text);
