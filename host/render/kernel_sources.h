// The trace kernel's sources compiled into the binary (generated from shaders/ at build
// time by tools/build/embed_shaders.cmake), and the ways to reach them.
#pragma once

#include "gpu/shader_compiler.h"

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

// File name (e.g. "trace.comp", "shared.h") to its text.
const std::map<std::string, std::string_view>& embeddedShaderSources();

// A loader over the sources compiled into the binary.
ShaderSourceLoader embeddedShaderLoader();

// Writes every embedded source into directory (created if missing), for --dump-shaders.
// Throws std::runtime_error naming the file that could not be written.
void writeEmbeddedShaders(const std::filesystem::path& directory);
