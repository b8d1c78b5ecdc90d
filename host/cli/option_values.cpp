#include "cli/option_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

std::uint32_t parseCount(const std::string& flag, const std::string& text, std::uint32_t low,
                         std::uint32_t high) {
    std::uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < low || value > high)
        throw UsageError(flag + " expects a whole number from " + std::to_string(low) + " to " +
                         std::to_string(high) + ", got '" + text + "'");
    return value;
}

double parseReal(const std::string& flag, const std::string& text) {
    double value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw UsageError(flag + " expects a number, got '" + text + "'");
    return value;
}

namespace {

// Numbers separated by commas, each a parseReal.
std::vector<double> realsSeparatedByCommas(const std::string& flag, const std::string& text) {
    std::vector<double> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        values.push_back(parseReal(flag, text.substr(start, comma - start)));
        if (comma == std::string::npos) return values;
        start = comma + 1;
    }
}

} // namespace

glm::dvec3 parseColor(const std::string& flag, const std::string& text) {
    const std::vector<double> channels = realsSeparatedByCommas(flag, text);
    if (channels.size() != 3 || channels[0] < 0 || channels[1] < 0 || channels[2] < 0)
        throw UsageError(flag + " expects three non-negative numbers R,G,B, got '" + text + "'");
    return {channels[0], channels[1], channels[2]};
}

glm::dvec3 parseVector(const std::string& flag, const std::string& text) {
    const std::vector<double> values = realsSeparatedByCommas(flag, text);
    if (values.size() != 3)
        throw UsageError(flag + " expects three numbers X,Y,Z, got '" + text + "'");
    return {values[0], values[1], values[2]};
}

glm::uvec2 parsePixel(const std::string& flag, const std::string& text) {
    const std::size_t comma = text.find(',');
    auto whole = [&](std::string_view part, std::uint32_t& value) {
        auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        return !part.empty() && error == std::errc() && end == part.data() + part.size();
    };
    glm::uvec2 pixel{0};
    if (comma == std::string::npos || !whole(std::string_view(text).substr(0, comma), pixel.x) ||
        !whole(std::string_view(text).substr(comma + 1), pixel.y))
        throw UsageError(flag +
                         " expects a pixel X,Y (column and row, whole numbers from 0), got '" +
                         text + "'");
    return pixel;
}

namespace {

// Whole numbers from 0 separated by separator, exactly count of them; empty when text is not that.
std::vector<std::uint32_t> wholeNumbers(const std::string& text, std::size_t count,
                                        char separator) {
    std::vector<std::uint32_t> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        const std::string_view part =
            std::string_view(text).substr(start, end == std::string::npos ? end : end - start);
        std::uint32_t value = 0;
        auto [stop, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || error != std::errc() || stop != part.data() + part.size()) return {};
        values.push_back(value);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return values.size() == count ? values : std::vector<std::uint32_t>{};
}

} // namespace

glm::uvec4 parseCrop(const std::string& flag, const std::string& text) {
    const std::vector<std::uint32_t> values = wholeNumbers(text, 4, ',');
    if (values.empty() || values[2] == 0 || values[3] == 0)
        throw UsageError(flag +
                         " expects a region X,Y,W,H (left column, top row, width and height; "
                         "whole numbers, W and H from 1), got '" +
                         text + "'");
    return {values[0], values[1], values[2], values[3]};
}

std::vector<std::uint32_t> parseSampleCounts(const std::string& flag, const std::string& text) {
    std::vector<std::uint32_t> counts;
    for (std::size_t n = 1; n <= 64 && counts.empty(); ++n)
        counts = wholeNumbers(text, n, ',');
    std::vector<std::uint32_t> sorted = counts;
    std::sort(sorted.begin(), sorted.end());
    if (counts.empty() || counts.front() == 0 || counts != sorted ||
        std::adjacent_find(counts.begin(), counts.end()) != counts.end())
        throw UsageError(flag +
                         " expects sample counts K,K,... (up to 64 whole numbers from 1, "
                         "increasing), got '" +
                         text + "'");
    return counts;
}

glm::uvec2 parseFrameRange(const std::string& flag, const std::string& text) {
    std::vector<std::uint32_t> values = wholeNumbers(text, 2, '-');
    if (values.empty()) values = wholeNumbers(text, 1, '-');
    if (values.size() == 1) values.push_back(values[0]);
    if (values.empty() || values[0] > values[1])
        throw UsageError(flag +
                         " expects FIRST-LAST or one frame K (whole numbers from 0, FIRST "
                         "at most LAST), got '" +
                         text + "'");
    return {values[0], values[1]};
}
