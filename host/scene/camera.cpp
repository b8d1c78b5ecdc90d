#include "scene/camera.h"

#include "scene/scene_triangles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// Orbit and look stop this far (radians) from looking straight along up, where the
// basis would flip.
constexpr double kPoleMargin = 0.01;
// Each wheel step moves this fraction of the distance nearer.
constexpr double kDollyFactorPerStep = 0.85;
// Dolly stops this near the target (world units), so the eye never reaches or passes it.
constexpr double kMinimumDistance = 1e-4;

bool finite(glm::dvec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// v turned by angle around the unit axis (Rodrigues' formula, exact for angle 0).
glm::dvec3 rotateAround(glm::dvec3 v, glm::dvec3 axis, double angle) {
    if (angle == 0.0) return v;
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

// direction turned by yaw around up and by pitch towards up, with the angle between
// direction and up kept within [kPoleMargin, pi - kPoleMargin].
glm::dvec3 turn(glm::dvec3 direction, glm::dvec3 up, double yaw, double pitch) {
    up = glm::normalize(up);
    glm::dvec3 turned = rotateAround(direction, up, yaw);
    const double length = glm::length(turned);
    const double polar = std::acos(std::clamp(glm::dot(turned / length, up), -1.0, 1.0));
    const double wanted = std::clamp(polar - pitch, kPoleMargin, M_PI - kPoleMargin);
    const glm::dvec3 side = glm::cross(turned, up);
    if (glm::length(side) == 0.0) return turned; // already on the pole; only yaw applies
    // A positive turn around cross(direction, up) moves direction towards up.
    return rotateAround(turned, glm::normalize(side), polar - wanted);
}

} // namespace

std::string cameraPoseProblem(const CameraPose& pose) {
    if (!finite(pose.position) || !finite(pose.target) || !finite(pose.up))
        return "the camera position, target and up must be finite numbers";
    const glm::dvec3 view = pose.target - pose.position;
    if (glm::length(view) == 0.0) return "the camera target must differ from the camera position";
    if (glm::length(pose.up) == 0.0) return "the camera up vector must not be zero";
    if (glm::length(glm::cross(glm::normalize(view), glm::normalize(pose.up))) < 1e-9)
        return "the camera up vector must not be parallel to the view direction";
    return {};
}

CameraBasis cameraBasis(const CameraPose& pose) {
    CameraBasis basis;
    basis.forward = glm::normalize(pose.target - pose.position);
    basis.right = glm::normalize(glm::cross(basis.forward, pose.up));
    basis.up = glm::cross(basis.right, basis.forward);
    return basis;
}

glm::dquat cameraOrientation(const CameraPose& pose) {
    const CameraBasis basis = cameraBasis(pose);
    // Columns: where camera +x, +y and +z (= -forward) go in the world.
    const glm::dmat3 rotation(basis.right, basis.up, -basis.forward);
    // For the identity matrix glm's conversion takes its w branch: w = sqrt(4) / 2 = 1 and
    // x = y = z = 0 exactly.
    return glm::normalize(glm::quat_cast(rotation));
}

CameraPose orbitCamera(const CameraPose& pose, double yawRadians, double pitchRadians) {
    CameraPose result = pose;
    // Turning the eye's offset from the target towards up raises the eye over the target.
    result.position =
        pose.target + turn(pose.position - pose.target, pose.up, yawRadians, pitchRadians);
    return result;
}

CameraPose dollyCamera(const CameraPose& pose, double steps) {
    const glm::dvec3 offset = pose.position - pose.target;
    const double distance = glm::length(offset);
    const double wanted =
        std::max(distance * std::pow(kDollyFactorPerStep, steps), kMinimumDistance);
    CameraPose result = pose;
    result.position = pose.target + offset * (wanted / distance);
    return result;
}

CameraPose flyCamera(const CameraPose& pose, glm::dvec3 move) {
    const CameraBasis basis = cameraBasis(pose);
    const glm::dvec3 delta =
        basis.right * move.x + glm::normalize(pose.up) * move.y + basis.forward * move.z;
    CameraPose result = pose;
    result.position += delta;
    result.target += delta;
    return result;
}

CameraPose lookCamera(const CameraPose& pose, double yawRadians, double pitchRadians) {
    CameraPose result = pose;
    result.target =
        pose.position + turn(pose.target - pose.position, pose.up, yawRadians, pitchRadians);
    return result;
}

SceneBounds sceneBounds(const Scene& scene) {
    glm::dvec3 low(std::numeric_limits<double>::infinity()),
        high(-std::numeric_limits<double>::infinity());
    for (const Sphere& sphere : scene.spheres) {
        low = glm::min(low, sphere.center - sphere.radius);
        high = glm::max(high, sphere.center + sphere.radius);
    }
    for (const Triangle& triangle : scene.triangles)
        for (const Vertex& vertex : triangle.vertices) {
            low = glm::min(low, vertex.position);
            high = glm::max(high, vertex.position);
        }
    for (const Mesh& mesh : scene.meshes) // every vertex is some triangle's corner
        for (const glm::dvec3& position : mesh.positions) {
            low = glm::min(low, position);
            high = glm::max(high, position);
        }
    if (!(low.x <= high.x)) return {};
    return {(low + high) * 0.5, glm::length(high - low) * 0.5};
}

namespace {

// A box grown point by point; empty until the first.
struct Box {
    glm::dvec3 low{std::numeric_limits<double>::infinity()}, high{-low};
    void add(glm::dvec3 a, glm::dvec3 b) {
        low = glm::min(low, a);
        high = glm::max(high, b);
    }
    bool empty() const { return !(low.x <= high.x); }
};

// A triangle's size for telling objects from floors, walls and backdrops (kSubjectShare).
double longestEdge(const Triangle& triangle) {
    const glm::dvec3 a = triangle.vertices[0].position, b = triangle.vertices[1].position,
                     c = triangle.vertices[2].position;
    return std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

} // namespace

SceneBounds subjectBounds(const Scene& scene, const CameraPose& camera, double fovDegrees,
                          double aspect) {
    if (scene.model)
        return {(scene.model->placedLow + scene.model->placedHigh) * 0.5,
                glm::length(scene.model->placedHigh - scene.model->placedLow) * 0.5};
    const SceneBounds whole = sceneBounds(scene);
    const double large = kSubjectShare * 2.0 * whole.radius;
    const CameraBasis basis = cameraBasis(camera);
    const double tanY = std::tan(fovDegrees * (M_PI / 180.0) / 2.0), tanX = tanY * aspect;
    auto inView = [&](glm::dvec3 p) {
        const glm::dvec3 d = p - camera.position;
        const double z = glm::dot(d, basis.forward);
        return z > 0.0 && std::abs(glm::dot(d, basis.right)) <= z * tanX &&
               std::abs(glm::dot(d, basis.up)) <= z * tanY;
    };
    // Small primitives in view; failing those, small ones anywhere; failing those, all.
    Box seen, small;
    for (const Sphere& sphere : scene.spheres) {
        if (2.0 * sphere.radius > large) continue;
        const glm::dvec3 r(sphere.radius);
        small.add(sphere.center - r, sphere.center + r);
        if (inView(sphere.center)) seen.add(sphere.center - r, sphere.center + r);
    }
    forEachTriangle(scene, [&](const Triangle& triangle) {
        const glm::dvec3 a = triangle.vertices[0].position, b = triangle.vertices[1].position,
                         c = triangle.vertices[2].position;
        if (longestEdge(triangle) > large) return; // a floor, a wall or a backdrop
        const glm::dvec3 low = glm::min(a, glm::min(b, c)), high = glm::max(a, glm::max(b, c));
        small.add(low, high);
        if (inView(a) || inView(b) || inView(c)) seen.add(low, high);
    });
    const Box& box = !seen.empty() ? seen : small;
    if (box.empty()) return whole;
    return {(box.low + box.high) * 0.5, glm::length(box.high - box.low) * 0.5};
}

CameraPose pivotAtScene(const CameraPose& pose, const SceneBounds& bounds, double minimumDistance) {
    const glm::dvec3 forward = cameraBasis(pose).forward;
    const double depth =
        std::max(glm::dot(bounds.centre - pose.position, forward), minimumDistance);
    CameraPose result = pose;
    result.target = pose.position + forward * depth;
    return result;
}

CameraPose turntableCamera(const CameraPose& pose, glm::dvec3 centre, std::uint32_t frame,
                           std::uint32_t frames) {
    return turntableCamera(pose, centre, glm::normalize(pose.up), frame, frames);
}

CameraPose turntableCamera(const CameraPose& pose, glm::dvec3 centre, glm::dvec3 axis,
                           std::uint32_t frame, std::uint32_t frames) {
    if (frame == 0 || frames == 0) return pose;
    const double angle = 2.0 * M_PI * double(frame) / double(frames);
    CameraPose turned = pose;
    turned.position = centre + rotateAround(pose.position - centre, axis, angle);
    turned.target = centre + rotateAround(pose.target - centre, axis, angle);
    if (glm::normalize(pose.up) != axis) turned.up = rotateAround(pose.up, axis, angle);
    return turned;
}

glm::dvec3 floorAxis(const Scene& scene, glm::dvec3 up) {
    up = glm::normalize(up);
    const double large = kSubjectShare * 2.0 * sceneBounds(scene).radius;
    double largest = 0.0;
    glm::dvec3 axis = up;
    forEachTriangle(scene, [&](const Triangle& triangle) {
        const glm::dvec3 a = triangle.vertices[0].position, b = triangle.vertices[1].position,
                         c = triangle.vertices[2].position;
        if (longestEdge(triangle) <= large) return; // an object, not a floor
        const glm::dvec3 normal = glm::cross(b - a, c - a);
        const double area = glm::length(normal);
        if (!(area > largest)) return;
        const double along = glm::dot(normal, up) / area;
        if (std::abs(along) < std::sqrt(0.5)) return; // a wall or a backdrop
        largest = area;
        axis = (along > 0.0 ? normal : -normal) / area;
    });
    return axis;
}
