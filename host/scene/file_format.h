// What a file that should be scene text or an OBJ model is instead, told from its first
// bytes: another model format (PLY, STL, glTF) or UTF-16 text, so that the error names it
// rather than calling it binary or reporting that no faces were found.
#pragma once

#include <optional>
#include <string>
#include <string_view>

enum class OtherFormat { Utf16Text, Ply, Stl, Gltf, BinaryGltf };

// One of those, or nothing for anything else (scene text, OBJ text, or other bytes).
std::optional<OtherFormat> otherFileFormat(std::string_view text);

// "UTF-16 text", "a PLY model", "an STL model", "a glTF model", "a binary glTF model (.glb)".
std::string formatName(OtherFormat format);

// What the file was read as.
enum class ExpectedFile { Scene, ObjModel };

// The error's message for a file of that format: what it is, and what to do about it.
std::string otherFormatMessage(OtherFormat format, const std::string& fileName,
                               ExpectedFile expected);
