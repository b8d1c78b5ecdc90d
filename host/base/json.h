// JSON text for every report the project writes (--bench, --pixel, the reference's story,
// the CPU peers): one way to quote a string and to write a number, so that all of them
// read alike and parse anywhere.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

// text as a JSON string literal: quotes and backslashes escaped, control characters as \uXXXX.
inline std::string jsonString(std::string_view text) {
    std::string quoted = "\"";
    for (char c : text) {
        if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
            quoted += escaped;
            continue;
        }
        if (c == '"' || c == '\\') quoted += '\\';
        quoted += c;
    }
    return quoted + "\"";
}

// A time or a rate with three decimals.
inline std::string jsonNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

// A value to this many significant digits (9 give a float back exactly, 17 a double);
// null when it is not finite, which JSON cannot spell.
inline std::string jsonNumber(double value, int significantDigits) {
    if (!std::isfinite(value)) return "null";
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", significantDigits, value);
    return text;
}

// The first three components of a vector (glm's, of any type) as [x, y, z].
template <typename Vector> std::string jsonTriple(const Vector& v, int significantDigits) {
    return "[" + jsonNumber(double(v.x), significantDigits) + ", " +
           jsonNumber(double(v.y), significantDigits) + ", " +
           jsonNumber(double(v.z), significantDigits) + "]";
}
