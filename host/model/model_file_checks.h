// What a model file's header claims, checked against the file before a reader library
// (assimp_model.h) sees it: a library may allocate what a header claims, or read past
// a chunk's end, on a damaged or hostile file. Each returns what is wrong, or nothing.
#pragma once

#include <optional>
#include <string>
#include <string_view>

// A GLB file: its header's length is the file's, and each chunk's length fits in what
// follows it.
std::optional<std::string> glbFramingProblem(std::string_view bytes);
