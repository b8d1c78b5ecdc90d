// Command-line values for the small tools beside the reference renderer (reference_render,
// stability_check, image_diff): one way to read a number and to say what was wrong.
#pragma once

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include <glm/glm.hpp>

namespace tool_arguments {

// A command line that makes no sense; the tools print what() and exit 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The whole of text as a T; a floating-point value must be finite.
template <typename T> T parseNumber(std::string_view option, std::string_view text) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        throw UsageError(std::string(option) + " expects a number, got '" + std::string(text) +
                         "'");
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(value))
            throw UsageError(std::string(option) + " expects a finite number, got '" +
                             std::string(text) + "'");
    return value;
}

// A whole number of at least minimum.
inline int parseCount(std::string_view option, std::string_view text, int minimum) {
    const int value = parseNumber<int>(option, text);
    if (value < minimum)
        throw UsageError(std::string(option) + " must be at least " + std::to_string(minimum) +
                         ", got " + std::string(text));
    return value;
}

// A vertical field of view in degrees, strictly between 0 and 180.
inline double parseFov(std::string_view option, std::string_view text) {
    const double degrees = parseNumber<double>(option, text);
    if (!(degrees > 0 && degrees < 180))
        throw UsageError(std::string(option) + " must be between 0 and 180 degrees");
    return degrees;
}

// Three numbers X,Y,Z; with signedValues false none may be negative (a colour).
inline glm::dvec3 parseTriple(std::string_view option, std::string_view text, bool signedValues) {
    glm::dvec3 value;
    for (int k = 0; k < 3; ++k) {
        const std::size_t comma = text.find(',');
        if ((k < 2) != (comma != std::string_view::npos))
            throw UsageError(std::string(option) + " expects three numbers separated by commas");
        value[k] = parseNumber<double>(option, text.substr(0, comma));
        if (!signedValues && value[k] < 0)
            throw UsageError(std::string(option) + " components must not be negative");
        text = k < 2 ? text.substr(comma + 1) : std::string_view();
    }
    return value;
}

} // namespace tool_arguments
