#include "scene/camera_path.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace {

// "X,Y,Z", each read exactly as the command line reads it (from_chars), so a line that
// spells the default camera renders the plain image byte for byte.
bool parseTriple(std::string_view text, glm::dvec3& value) {
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t comma = axis < 2 ? text.find(',') : text.size();
        if (comma == std::string_view::npos) return false;
        const std::string_view part = text.substr(0, comma);
        double number = 0;
        auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), number);
        if (part.empty() || error != std::errc() || end != part.data() + part.size() ||
            !std::isfinite(number))
            return false;
        value[axis] = number;
        text = axis < 2 ? text.substr(comma + 1) : std::string_view();
    }
    return true;
}

std::vector<std::string_view> fieldsOf(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t at = 0;
    while (true) {
        at = line.find_first_not_of(" \t\r", at);
        if (at == std::string_view::npos) break;
        const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
        fields.push_back(line.substr(at, end - at));
        at = end;
    }
    return fields;
}

PathCamera parseLine(std::string_view line, const std::string& fileName, int number) {
    const std::vector<std::string_view> fields = fieldsOf(line);
    if (fields.size() != 4)
        throw SceneError(fileName, number,
                         "expected 4 fields, POSITION TARGET UP FOV (as in 0,0,0 0,0,-1 0,1,0 "
                         "60), got " +
                             std::to_string(fields.size()));
    PathCamera camera;
    camera.line = number;
    const char* names[] = {"position", "target", "up"};
    glm::dvec3* values[] = {&camera.pose.position, &camera.pose.target, &camera.pose.up};
    for (int i = 0; i < 3; ++i)
        if (!parseTriple(fields[i], *values[i]))
            throw SceneError(fileName, number,
                             std::string(names[i]) + " expects three numbers X,Y,Z, got '" +
                                 std::string(fields[i]) + "'");
    auto [end, error] =
        std::from_chars(fields[3].data(), fields[3].data() + fields[3].size(), camera.fovDegrees);
    if (error != std::errc() || end != fields[3].data() + fields[3].size() ||
        !(camera.fovDegrees > 0.0 && camera.fovDegrees < 180.0))
        throw SceneError(fileName, number,
                         "fov expects degrees strictly between 0 and 180, got '" +
                             std::string(fields[3]) + "'");
    if (std::string problem = cameraPoseProblem(camera.pose); !problem.empty())
        throw SceneError(fileName, number, problem);
    return camera;
}

} // namespace

std::vector<PathCamera> parseCameraPath(std::string_view text, const std::string& fileName) {
    std::vector<PathCamera> cameras;
    int number = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        ++number;
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
        cameras.push_back(parseLine(line, fileName, number));
    }
    if (cameras.empty())
        throw SceneError(fileName, 0, "no camera in the file (one a line: POSITION TARGET UP FOV)");
    return cameras;
}

std::vector<PathCamera> loadCameraPath(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw SceneError(path.string(), 0,
                         std::string("cannot open file: ") + std::strerror(EISDIR));
    std::ifstream file(path, std::ios::binary);
    if (!file)
        throw SceneError(path.string(), 0,
                         std::string("cannot open file: ") + std::strerror(errno));
    std::ostringstream text;
    text << file.rdbuf();
    return parseCameraPath(text.str(), path.string());
}
