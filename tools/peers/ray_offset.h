// Self-intersection avoidance for the peers' shadow and reflection rays: the same method
// as the GPU kernel (shaders/ray_offset.glsl), so the peers do the same work and a
// difference in their images points at the intersector, not at this choice.
//
// Waechter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray
// Tracing Gems ch. 6 (2019): each coordinate moves 256 ULPs of `magnitude` (the sum of
// the absolute terms it was computed from) along the normal, or, near zero, by an
// absolute step relative to the point's scale. No fixed epsilon: it holds for scenes
// from 1e-4 to 1e5 across (snow.scene), so no tnear is needed (tnear = 0).
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>

// Moves p off its surface along the unit geometric normal n, which points to the side
// the new ray leaves on.
inline glm::vec3 offsetRayOrigin(glm::vec3 p, glm::vec3 n, glm::vec3 magnitude) {
    constexpr float originBand = 1.0f / 32.0f;    // coordinates below scale/32: absolute step
    constexpr float floatScale = 1.0f / 65536.0f; // absolute step: scale/65536 times n
    constexpr float intScale = 256.0f;            // elsewhere: 256 ULPs of magnitude times n
    const float scale = std::max(magnitude.x, std::max(magnitude.y, magnitude.z));
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) {
        if (magnitude[k] < originBand * scale) {
            out[k] = p[k] + floatScale * scale * n[k];
        } else {
            const auto bits = std::bit_cast<std::int32_t>(magnitude[k]);
            const float moved = std::bit_cast<float>(bits + std::int32_t(intScale * n[k]));
            out[k] = p[k] + (moved - magnitude[k]); // the difference is exact
        }
    }
    return out;
}
