// -o as a pattern for many images (docs/batches.md): {name} is the scene file's stem,
// {frame} the frame number and {frame:04} the same zero-padded to 4 digits (any width from
// 1 to 9). A folder (a path ending in '/', or for a batch an existing folder) stands for
// {name}.png in it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

// True for "out/" and for the name of an existing folder.
bool isOutputFolder(const std::filesystem::path& output);

// The pattern a folder stands for: FOLDER/{name}.png, or FOLDER/{name}-{frame:04}.png
// when there are frames.
std::filesystem::path folderOutputPattern(const std::filesystem::path& folder, bool frames);

// Why pattern is not one (an unknown field, a '{' left open, a bad width), or empty when it is.
std::string outputPatternProblem(const std::string& pattern);

// Whether pattern holds the field: "name" or "frame" (with or without a width).
bool outputPatternHas(const std::string& pattern, const std::string& field);

// The file for one image: every field replaced. pattern must be one (outputPatternProblem).
std::filesystem::path expandOutputPattern(const std::string& pattern, const std::string& name,
                                          std::uint32_t frame);
