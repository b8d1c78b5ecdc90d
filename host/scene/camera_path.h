// --camera-path FILE: the cameras of an animation, one a line (docs/batches.md):
//
//     POSITION TARGET UP FOV        e.g.   0,0,0  0,0,-1  0,1,0  60
//
// POSITION, TARGET and UP are X,Y,Z as --camera-pos, --camera-target and --camera-up take
// them, FOV the vertical field of view in degrees as --fov; fields are separated by spaces
// or tabs. '#' starts a comment to the end of the line; blank lines are skipped. Errors are
// SceneErrors, "FILE:LINE: error: ...", like a scene file's.
#pragma once

#include "scene/camera.h"
#include "scene/scene_error.h"

#include <filesystem>
#include <string_view>
#include <vector>

struct PathCamera {
    CameraPose pose;
    double fovDegrees = 60.0;
    int line = 0; // where it was in the file
};

// The cameras of text, in order; fileName is for messages. At least one, or a SceneError.
std::vector<PathCamera> parseCameraPath(std::string_view text, const std::string& fileName);

// Reads FILE and parses it; a missing or unreadable file is a SceneError.
std::vector<PathCamera> loadCameraPath(const std::filesystem::path& path);
