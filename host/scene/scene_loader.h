// Scene text to a Scene: the entry points of the scene folder. A small text is read in one
// pass; a large one is shared among threads (scene_loader.cpp), with exactly the result,
// errors and warnings of one pass.
#pragma once

#include "scene/obj_scene.h"
#include "scene/scene.h"
#include "scene/scene_error.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

// Parses scene text. fileName is used in messages only.
Scene parseScene(std::string_view text, const std::string& fileName);

// How parseScene shares a large text among threads. The result, errors included, is
// the same for any setting; the defaults suit every caller, and the tests shrink the
// chunks to take the parallel path on small texts.
struct SceneParseOptions {
    unsigned threads = 0;                 // 0: workerThreads() (base/parallel.h)
    std::size_t minChunkBytes = 1u << 20; // no thread gets less text than this
};
Scene parseScene(std::string_view text, const std::string& fileName,
                 const SceneParseOptions& options);

// Reads and parses a file; a missing, unreadable or binary file is a SceneError. A path
// ending in .obj is read as a Wavefront OBJ model and made a scene by the rules of
// obj_scene.h (docs/models.md); one ending in .ply is refused with a message.
Scene loadScene(const std::filesystem::path& path, const ObjSceneSetup& modelSetup = {});
