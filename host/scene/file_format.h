// What a file that should be scene text or an OBJ model is instead, told from its first
// bytes: another model format (PLY, STL, glTF) or UTF-16 text, so that the error names it
// rather than calling it binary or reporting that no faces were found.
#pragma once

#include <optional>
#include <string>
#include <string_view>

// "a PLY model", "an STL model", "a glTF model", "a binary glTF model (.glb)", or
// "UTF-16 text"; nothing for anything else (scene text, OBJ text, or other bytes).
std::optional<std::string> otherFileFormat(std::string_view text);

// The error's message for a file of that format read as `expected` ("a scene file" or "an
// OBJ model"): what it is, and what to do about it.
std::string otherFormatMessage(const std::string& format, const std::string& fileName,
                               const std::string& expected);
