// Wavefront OBJ text (and the MTL files it names) to a SourceModel. The rules, which
// tools/obj_to_scene.py follows too, are in docs/models.md: faces of 3 or more corners
// (v, v/vt, v/vt/vn, v//vn; 1-based or negative indices), split into triangles
// (polygon_triangulation.h: a fan when convex, ear clipping when concave); vn as given; vt;
// `v x y z r g b` colours; the materials of mtl_reader.h. Groups and smoothing groups are read
// and ignored. A malformed line is a SceneError "FILE:LINE: error: ..."; a binary file is not
// an OBJ file. A large text is read by all threads at once (obj_survey.h, obj_fill.h),
// to the same model, warnings and first error as one pass.
#pragma once

#include "model/mtl_reader.h"
#include "model/source_model.h"
#include "scene/scene_capacity.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

// How the text is shared among threads: in up to `chunks` chunks (0: kObjChunksPerThread a
// thread of workerThreads(), obj_survey.h), none shorter than minChunkBytes. The model, its
// warnings and its errors are the same whatever the split.
// With a capacity, a file of more triangles than the device holds is refused once the survey
// has counted them, before the text is read.
struct ObjParseOptions {
    unsigned chunks = 0;
    std::size_t minChunkBytes = 1u << 20;
    const SceneCapacity* capacity = nullptr;
};

// fileName is used in messages; lookUpMtl finds the libraries that mtllib names.
SourceModel parseObj(std::string_view text, const std::string& fileName, const MtlLookup& lookUpMtl,
                     const ObjParseOptions& options = {});

// The model in text, the file at path (whose name is used in messages), with the
// libraries beside it that it names.
SourceModel readObjFile(const std::filesystem::path& path, std::string_view text,
                        const SceneCapacity* capacity = nullptr);
