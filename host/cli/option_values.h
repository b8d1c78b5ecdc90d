// The values of command-line options, each read from its text or refused with a
// UsageError that names the flag, says what it expects and quotes what it got.
#pragma once

#include "cli/usage_error.h"
#include "packing/kernel_choices.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

// A whole number from low to high.
std::uint32_t parseCount(const std::string& flag, const std::string& text, std::uint32_t low,
                         std::uint32_t high);
// A finite number.
double parseReal(const std::string& flag, const std::string& text);
// Three non-negative numbers R,G,B.
glm::dvec3 parseColor(const std::string& flag, const std::string& text);
// Three numbers X,Y,Z of any sign (a point or a direction).
glm::dvec3 parseVector(const std::string& flag, const std::string& text);
// --pixel X,Y: a column and a row, whole numbers (checked against the image size later).
glm::uvec2 parsePixel(const std::string& flag, const std::string& text);
// --crop X,Y,W,H: the region's left column, top row, width and height (checked against the
// image size later).
glm::uvec4 parseCrop(const std::string& flag, const std::string& text);
// --frames FIRST-LAST or --frames K: frame numbers from 0, inclusive.
glm::uvec2 parseFrameRange(const std::string& flag, const std::string& text);

// --snapshots K,K,...: 1 to 64 sample counts from 1, strictly increasing.
std::vector<std::uint32_t> parseSampleCounts(const std::string& flag, const std::string& text);

// One of names' values by its name; the message lists them ("grid, stratified or r2").
template <typename T>
T parseChoice(const std::string& flag, const std::string& text, const ChoiceNames<T>& names) {
    std::string expected;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i].first == text) return names[i].second;
        expected += (i == 0                  ? ""
                     : i + 1 == names.size() ? " or "
                                             : ", ") +
                    std::string(names[i].first);
    }
    throw UsageError(flag + " expects " + expected + ", got '" + text + "'");
}
