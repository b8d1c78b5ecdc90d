// Scene text to a Scene: the entry point of the scene folder (a file of any kind, scene or
// model, is read by model/scene_file.h). A small text is read in one pass; a large one is
// shared among threads (scene_loader.cpp), with exactly the result, errors and warnings of
// one pass.
#pragma once

#include "scene/scene.h"
#include "scene/scene_error.h"

#include <cstddef>
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
