// What a file that should be scene text or an OBJ model is instead, told from its first
// bytes: another model format (PLY, STL, glTF) or UTF-16 text, so that the error names it
// rather than calling it binary or reporting that no faces were found.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

enum class OtherFormat { Utf16Text, Ply, Stl, Gltf, BinaryGltf };

// Whether the bytes are a binary STL: an 80-byte header, a triangle count, then 50 bytes a
// triangle, exactly (whatever the header says: some begin it with "solid").
bool isBinaryStl(std::string_view text);

// One of those, or nothing for anything else (scene text, OBJ text, or other bytes).
std::optional<OtherFormat> otherFileFormat(std::string_view text);

// "UTF-16 text", "a PLY model", "an STL model", "a glTF model", "a binary glTF model (.glb)".
std::string formatName(OtherFormat format);

// What the file was read as.
enum class ExpectedFile { Scene, SourceModel };

// The error's message for a file of that format: what it is, and what to do about it.
std::string otherFormatMessage(OtherFormat format, const std::string& fileName,
                               ExpectedFile expected);

// Whether a path names an OBJ model: its extension, .obj in any case.
bool isObjPath(const std::filesystem::path& path);
// Whether a path names a PLY model: .ply in any case.
bool isPlyPath(const std::filesystem::path& path);
// Whether a path names an STL model: .stl in any case.
bool isStlPath(const std::filesystem::path& path);
// Whether a path names a model that assimp reads (assimp_model.h) by its extension, in any
// case: .gltf, .glb (which otherFileFormat also tells by their bytes), .fbx, .dae, .3ds
// and .off.
bool isAssimpPath(const std::filesystem::path& path);
// Any of those: a model rather than a scene file, by its name.
bool isModelPath(const std::filesystem::path& path);
