// How far from the eye a model goes so that its silhouette fills the frame: the fit of a
// model placed for the default camera (model/model_scene.h), and the same fit again for each
// frame of a turntable, whose camera sees the model from another side.
#pragma once

#include "scene/camera.h"

#include <glm/glm.hpp>

#include <vector>

// The silhouette spans this share of the frame's width or height (the larger share).
inline constexpr double kFrameShare = 0.8;
// ... but no position lies further than this share of the way to the frame's edge.
inline constexpr double kFrameLimit = 0.95;

// The distance straight ahead of the eye at which `turned` (positions relative to the point
// looked at, in camera axes: x right, y up, z towards the eye) fills kFrameShare of a view
// whose half-angles have tangents tanY and tanX; see fitDistance in model_fit.cpp.
double fitDistance(const std::vector<glm::dvec3>& turned, double tanY, double tanX);

// The pose with its eye moved along its line of sight, the target kept, to where positions
// (world space) fill the frame as fitDistance says, for a vertical field of view of
// fovDegrees and an aspect of width over height. The pose itself when positions is empty
// or the distance is not finite.
CameraPose refitCamera(const CameraPose& pose, const std::vector<glm::dvec3>& positions,
                       double fovDegrees, double aspect);
