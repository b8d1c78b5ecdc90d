// the model of docs/model.md on the CPU in float, shared by every peer: surface data at a hit,
// Phong with hard shadows, the reflection loop. It mirrors the GPU kernel (shaders/shade.glsl,
// trace.comp) step for step; only the intersector differs between peers, so a benchmark
// compares intersectors and nothing else.
//
// A peer supplies a Worker (one per thread) with
//   PeerHit closestHit(const PeerRay&)          nearest hit with t > 0, or kind none
//   bool occluded(const PeerRay&, float tMax)   any hit with 0 < t < tMax
// and, if it can do better on coherent rays, (cpu_render.h asks for a row at a time)
//   void closestHits(std::span<const PeerRay>, std::span<PeerHit>)   primary rays
// Ray directions are unit length; no tnear (ray_offset.h moves the origins instead).
#pragma once

#include "peer_scene.h"
#include "ray_offset.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

struct PeerRay {
    glm::vec3 origin;
    glm::vec3 direction;
};

enum class HitKind : std::uint8_t { none, sphere, triangle };

struct PeerHit {
    float t = 0.0f;
    HitKind kind = HitKind::none;
    std::uint32_t index = 0;  // into scene.spheres or scene.triangles
    float u = 0.0f, v = 0.0f; // triangles: the weights of corners 1 and 2 (Embree's u, v)
};

// Everything shading needs about a hit point.
struct PeerSurface {
    glm::vec3 position;
    glm::vec3 magnitude;       // per coordinate, sum of |terms| position was computed from
    glm::vec3 geometricNormal; // unit, either side
    glm::vec3 normal;          // unit shading normal, facing the incoming ray
    PeerMaterial material;
};

// v scaled to unit length, or fallback when v is zero; dividing by the largest
// component first keeps tiny and huge vectors in range.
inline glm::vec3 normalizeOr(glm::vec3 v, glm::vec3 fallback) {
    const float m = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
    return m > 0.0f ? glm::normalize(v / m) : fallback;
}

// Sphere: P projected back onto the sphere, N = (P - C) / r. Triangle: P, the normals
// and the materials interpolated with the barycentrics (P from the vertices rather than
// o + t d, so its error scales with the vertices only).
inline PeerSurface surfaceAt(const PeerScene& scene, const PeerRay& ray, const PeerHit& hit) {
    PeerSurface s;
    if (hit.kind == HitKind::sphere) {
        const glm::vec4 sphere = scene.spheres[hit.index];
        const glm::vec3 centre(sphere);
        const glm::vec3 radial =
            normalizeOr(ray.origin + hit.t * ray.direction - centre, -ray.direction);
        s.position = centre + sphere.w * radial;
        s.magnitude = glm::abs(centre) + sphere.w * glm::abs(radial);
        s.geometricNormal = radial;
        s.normal = radial;
        s.material = scene.sphereMaterials[hit.index];
    } else {
        const glm::uvec3 ids = scene.triangles[hit.index];
        const glm::vec3 a = scene.positions[ids.x], b = scene.positions[ids.y],
                        c = scene.positions[ids.z];
        const glm::vec3 w(1.0f - hit.u - hit.v, hit.u, hit.v);
        s.position = w.x * a + w.y * b + w.z * c;
        s.magnitude = w.x * glm::abs(a) + w.y * glm::abs(b) + w.z * glm::abs(c);
        s.geometricNormal = normalizeOr(glm::cross(b - a, c - a), -ray.direction);
        const PeerCorner* k = &scene.corners[3 * std::size_t(hit.index)];
        s.normal = normalizeOr(w.x * k[0].normal + w.y * k[1].normal + w.z * k[2].normal,
                               s.geometricNormal);
        s.material.kd = w.x * k[0].material.kd + w.y * k[1].material.kd + w.z * k[2].material.kd;
        s.material.ks = w.x * k[0].material.ks + w.y * k[1].material.ks + w.z * k[2].material.ks;
        s.material.shininess = w.x * k[0].material.shininess + w.y * k[1].material.shininess +
                               w.z * k[2].material.shininess;
        s.material.kr = w.x * k[0].material.kr + w.y * k[1].material.kr + w.z * k[2].material.kr;
    }
    if (glm::dot(s.normal, ray.direction) > 0.0f) s.normal = -s.normal;
    return s;
}

// A ray from the surface in unit direction d, its origin offset to the side d leaves on.
inline PeerRay leavingRay(const PeerSurface& s, glm::vec3 d) {
    const glm::vec3 side =
        glm::dot(s.geometricNormal, d) > 0.0f ? s.geometricNormal : -s.geometricNormal;
    return {offsetRayOrigin(s.position, side, s.magnitude), d};
}

// Counts the rays a thread traces, for the rays-per-second figures.
struct RayCount {
    std::uint64_t rays = 0;
};

// Local Phong colour seen along -view: ambient once, then for each unshadowed light in
// front of the surface Lc * (kd N.L + ks max(R.V, 0)^shininess).
template <typename Worker>
glm::vec3 shadePhong(const PeerScene& scene, Worker& worker, const PeerSurface& s, glm::vec3 view,
                     RayCount& count) {
    glm::vec3 color = scene.ambient;
    for (const PeerLight& light : scene.lights) {
        const glm::vec3 l = normalizeOr(light.position - s.position, glm::vec3(0.0f));
        const float nDotL = glm::dot(s.normal, l);
        if (nDotL <= 0.0f) continue;
        PeerRay shadow = leavingRay(s, l);
        const glm::vec3 toLight = light.position - shadow.origin;
        const float distance = glm::length(toLight);
        shadow.direction = toLight / distance;
        ++count.rays;
        if (worker.occluded(shadow, distance)) continue;
        const glm::vec3 r = 2.0f * nDotL * s.normal - l;
        const float rDotV = glm::dot(r, view);
        // pow(x, 0) is 1 for x > 0; the test keeps pow away from 0 and negative bases.
        const glm::vec3 specular =
            rDotV > 0.0f ? s.material.ks * std::pow(rDotV, s.material.shininess) : glm::vec3(0.0f);
        color += light.color * (s.material.kd * nDotL + specular);
    }
    return color;
}

// The model's recursion colour = (1 - ks) local + ks colour(reflected) (local alone when
// ks == 0 or at depth), unrolled into a loop carrying the product of the ks (throughput).
template <typename Worker>
glm::vec3 traceRay(const PeerScene& scene, Worker& worker, PeerRay ray, int depth,
                   glm::vec3 background, RayCount& count, const PeerHit* firstHit = nullptr) {
    glm::vec3 color(0.0f), throughput(1.0f);
    for (int bounce = 0;; ++bounce) {
        ++count.rays;
        const PeerHit hit = bounce == 0 && firstHit ? *firstHit : worker.closestHit(ray);
        if (hit.kind == HitKind::none) return color + throughput * background;
        const PeerSurface s = surfaceAt(scene, ray, hit);
        const glm::vec3 local = shadePhong(scene, worker, s, -ray.direction, count);
        const glm::vec3 ks = s.material.kr;
        if (ks == glm::vec3(0.0f) || bounce >= depth) return color + throughput * local;
        color += throughput * (1.0f - ks) * local;
        throughput *= ks;
        if (throughput == glm::vec3(0.0f)) return color; // nothing further can contribute
        ray = leavingRay(s, glm::normalize(glm::reflect(ray.direction, s.normal)));
    }
}
