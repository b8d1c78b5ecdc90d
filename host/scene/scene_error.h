// The one error of the scene reader: where the file went wrong and what was expected.
#pragma once

#include <stdexcept>
#include <string>

// A scene file that does not follow the format. what() reads
// "FILE:LINE: error: MESSAGE", ready to print.
struct SceneError : std::runtime_error {
    SceneError(std::string file, int line, std::string message);
    std::string file;
    int line;            // 1-based; 0 when the error concerns the whole file
    std::string message; // what was expected, without the location
};

// "FILE:LINE: " (or "FILE: " for line 0): how messages and warnings name a place.
std::string sceneLocation(const std::string& file, int line);
