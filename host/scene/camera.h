// The camera: where it is and where it looks (--camera-pos, --camera-target, --camera-up),
// its orientation for the kernel, and the window's orbit and fly controls as pure math on
// input deltas (host/window/input.cpp turns mouse and keys into these calls; no GLFW here).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <string>

// The default camera by default: the eye at the origin looking down -z, +y up.
struct CameraPose {
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};

    bool operator==(const CameraPose&) const = default;
};

// Why a pose has no orientation (target on the eye, up along the view, non-finite), or
// empty when it is usable.
std::string cameraPoseProblem(const CameraPose& pose);

// The camera's axes in world space: right (+x), up (+y) and forward (-z in camera space).
struct CameraBasis {
    glm::dvec3 right, up, forward;
};
CameraBasis cameraBasis(const CameraPose& pose);

// The unit quaternion that rotates camera space into world space: exactly the identity
// for the default camera, whose rays then stay bit for bit those of
// docs/model.md.
glm::dquat cameraOrientation(const CameraPose& pose);

// Orbit around the target, keeping the distance: yaw turns the eye around pose.up, a
// positive pitch raises it over the target, stopping short of the pole.
CameraPose orbitCamera(const CameraPose& pose, double yawRadians, double pitchRadians);

// Towards the target (steps > 0, a mouse wheel's clicks) or away, by a fixed factor per
// step; never reaches or passes the target.
CameraPose dollyCamera(const CameraPose& pose, double steps);

// Moves eye and target together by move.x along right, move.y along pose.up and move.z
// along forward (world units).
CameraPose flyCamera(const CameraPose& pose, glm::dvec3 move);

// Turns the view around the eye (mouse look): yaw around pose.up, a positive pitch looks
// up, stopping short of looking straight along up. The target keeps its distance.
CameraPose lookCamera(const CameraPose& pose, double yawRadians, double pitchRadians);

// A sphere around everything in the scene (spheres, triangles; lights ignored), for
// movement speeds and the orbit pivot. Radius 0 around the origin for an empty scene.
struct SceneBounds {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};
SceneBounds sceneBounds(const Scene& scene);

// A sphere around what the camera is there to see, for the turntable's centre, the window's
// pivot and its fly speed: a model's own box (its floor left out); else the box of the
// primitives no larger than kSubjectShare of the scene's extent (a sphere's diameter, a
// triangle's longest edge: floors, walls and backdrops are left out) that have a corner or
// centre inside the camera's view (fovDegrees vertical, aspect width over height); failing
// those, of the small ones anywhere; failing those, the whole scene.
inline constexpr double kSubjectShare = 0.25;
SceneBounds subjectBounds(const Scene& scene, const CameraPose& camera, double fovDegrees,
                          double aspect);

// The same view, with the target moved along the line of sight to the depth of the
// scene's centre (at least minimumDistance ahead), so that orbiting turns around the scene.
CameraPose pivotAtScene(const CameraPose& pose, const SceneBounds& bounds, double minimumDistance);

// Frame `frame` of `frames` of --turntable: eye and target turned by 2 pi frame / frames
// around the line through centre along pose.up (counter-clockwise seen from above, that is
// from +up), so the distance to that line and the height along it are kept. Frame 0 is
// pose itself, bit for bit.
CameraPose turntableCamera(const CameraPose& pose, glm::dvec3 centre, std::uint32_t frame,
                           std::uint32_t frames);
// The same about another axis (unit length): eye, target and up turned about the line
// through centre along axis.
CameraPose turntableCamera(const CameraPose& pose, glm::dvec3 centre, glm::dvec3 axis,
                           std::uint32_t frame, std::uint32_t frames);

// The axis a turntable turns the scene about: the normal of its floor, turned to up's side,
// where it has one (the largest triangle longer than kSubjectShare of the scene's extent,
// within 45 degrees of up: a ramp such as SIGGRAPH's or table's turns on itself, and the
// camera never passes below it), else up, normalised.
glm::dvec3 floorAxis(const Scene& scene, glm::dvec3 up);
