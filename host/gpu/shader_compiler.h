// GLSL to SPIR-V at run time with the glslang library. Sources come through a loader: from
// memory (render/kernel_sources.h: the copies embedded in the binary), or from a folder
// the user names (--shader-dir); never from the working directory by chance.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

// Returns the text of a shader file by its bare name ("shade.glsl"), or nothing.
using ShaderSourceLoader = std::function<std::optional<std::string>(const std::string& name)>;

// glslang's log, with file names and line numbers ("ERROR: trace.comp:12: ...").
struct ShaderCompileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Compiles the compute shader mainFile, resolving #include "x" through load. preamble
// (e.g. "#define RT_FP64 1\n") is seen before the source, without shifting its line numbers.
std::vector<std::uint32_t> compileComputeShader(const std::string& mainFile,
                                                const ShaderSourceLoader& load,
                                                const std::string& preamble = {});

// The compiler and how compileComputeShader calls it ("glslang X.Y.Z; vulkan1.2 spv1.5
// optimized; v1"): part of the key of cached SPIR-V, so a new glslang or new settings never
// reuse an old compile.
std::string shaderCompilerRecipe();

// The glslang this program was built with: "12.0.0".
std::string glslangVersion();

// A loader over the files of a folder (--shader-dir): "shade.glsl" is DIR/shade.glsl.
// Read afresh on every call, so a recompile sees the files as they are now.
ShaderSourceLoader directoryShaderLoader(const std::filesystem::path& directory);
