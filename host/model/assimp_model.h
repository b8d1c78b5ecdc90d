// Models in the formats other than OBJ, PLY and STL (glTF 2.0 and GLB, and what else the
// Open Asset Import Library reads: FBX, COLLADA, 3DS, OFF) read through assimp into the
// same SourceModel an OBJ file becomes, so that every rule of model_scene.h (up axis, fit,
// floor, rig, crease normals, far vertices) applies to them unchanged. docs/models.md
// states how each format's contents map onto it.
#pragma once

#include "model/source_model.h"
#include "scene/file_format.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

// The model in bytes (the file at path, whose name is used in messages; format as
// otherFileFormat told it, or none when the extension chose assimp). Corners at the same
// position, bit for bit, with the same colour become one position, as an OBJ file's `v`
// lines would be (glTF repeats a position where texture coordinates or normals part), so
// that smooth normals join them. Throws SceneError naming the file for a file assimp cannot read,
// or one with no triangles; a GLB file whose framing is wrong (model_file_checks.h) is refused
// before assimp sees it. assimp runs in a child process (contained_reader.h): a crash there is an
// error naming the file.
SourceModel readAssimpModel(std::string_view bytes, const std::filesystem::path& path,
                            std::optional<OtherFormat> format);
