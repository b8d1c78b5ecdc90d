#include "scene/scene_error.h"

#include <utility>

std::string sceneLocation(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

SceneError::SceneError(std::string fileName, int lineNumber, std::string text)
    : std::runtime_error(sceneLocation(fileName, lineNumber) + "error: " + text),
      file(std::move(fileName)), line(lineNumber), message(std::move(text)) {}
