// The vector arithmetic that models are built with, written out so that
// tools/obj_to_scene.py can do the same operations in the same order and write the same
// scene text: glm's own may order or fuse them otherwise.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace exact_vectors {

inline double length(glm::dvec3 v) {
    return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

inline glm::dvec3 normalizedOrZero(glm::dvec3 v) {
    const double n = length(v);
    return n > 0.0 ? glm::dvec3(v.x / n, v.y / n, v.z / n) : glm::dvec3(0.0);
}

inline double dot(glm::dvec3 a, glm::dvec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

} // namespace exact_vectors
