// Readers run in a child process: a reader library (assimp, stb) can crash on a damaged or
// hostile file, and that must end one read with a message naming the file, not the
// program. What the child read comes back through a pipe as bytes (model_bytes.h for a
// model; texture_decoder.cpp for images).
#pragma once

#include "model/source_model.h"

#include <functional>
#include <string>
#include <string_view>

// produce() run in a forked child; the bytes it returns come back. A SceneError it throws
// is thrown again here as it was; a crash or any other failure there is a SceneError naming
// fileName and how `reader` ("the model reader") ended.
std::string runContained(const std::string& fileName, const std::string& reader,
                         const std::function<std::string()>& produce);

// read() run in a forked child, by runContained, as "the model reader".
SourceModel readContained(const std::string& fileName, const std::function<SourceModel()>& read);
