// A reader run in a child process: a reader library (assimp) can crash on a damaged or
// hostile file, and that must end one read with a message naming the file, not the
// program. The model comes back through a pipe as bytes (model_bytes.h).
#pragma once

#include "model/obj_model.h"

#include <functional>
#include <string>

// read() run in a forked child. Its SceneError is thrown again here as it was; a crash or
// any other failure there is a SceneError naming fileName and how the reader ended.
ObjModel readContained(const std::string& fileName, const std::function<ObjModel()>& read);
