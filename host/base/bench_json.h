// Small helpers for the one-line JSON reports of --bench, shared by Raytracer and the
// CPU peers in tools/peers so that their reports read alike.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

// The median of the values (the mean of the middle two for an even count); not empty.
inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

// text as a JSON string literal, quotes, backslashes and control characters escaped.
inline std::string jsonString(const std::string& text) {
    std::string quoted = "\"";
    for (char c : text) {
        if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            quoted += escaped;
            continue;
        }
        if (c == '"' || c == '\\') quoted += '\\';
        quoted += c;
    }
    return quoted + "\"";
}

// A time or rate with three decimals.
inline std::string jsonNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}
