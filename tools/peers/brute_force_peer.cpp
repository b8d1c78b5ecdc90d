// brute_force_peer: the model of docs/model.md on the CPU with no acceleration structure, every ray
// against every primitive, in float over 2 threads. On scenes of a handful of objects
// nothing beats it; tools/bench runs it beside Raytracer and embree_peer.
//
// Spheres: the perpendicular-distance quadratic (Ray Tracing Gems ch. 7), stable for
// small far spheres. Triangles: Moeller-Trumbore on precomputed (v0, e1, e2), the
// classic choice for a brute-force loop (cheap, no per-ray setup).
#include "peer_driver.h"

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace {

struct EdgeTriangle {
    glm::vec3 v0, e1, e2; // corner 0 and the edges to corners 1 and 2
};

struct BruteForce {
    const std::vector<glm::vec4>* spheres;
    std::vector<EdgeTriangle> triangles;

    // Nearest root in (0, tMax) of |o + t d - c| = r (d unit): from the closest approach
    // of the line to the centre, so no b^2 - c cancellation. From inside: the far root.
    static bool hitSphere(const PeerRay& ray, glm::vec4 sphere, float tMax, float& t) {
        const glm::vec3 toCentre = glm::vec3(sphere) - ray.origin;
        const float along = glm::dot(toCentre, ray.direction);
        const glm::vec3 perpendicular = toCentre - along * ray.direction;
        const float h2 = sphere.w * sphere.w - glm::dot(perpendicular, perpendicular);
        if (h2 < 0.0f) return false;
        const float h = std::sqrt(h2);
        t = along - h > 0.0f ? along - h : along + h;
        return t > 0.0f && t < tMax;
    }

    // Moeller & Trumbore 1997, two-sided, edges inclusive; u, v weigh corners 1, 2.
    static bool hitTriangle(const PeerRay& ray, const EdgeTriangle& tri, float tMax, float& t,
                            float& u, float& v) {
        const glm::vec3 p = glm::cross(ray.direction, tri.e2);
        const float det = glm::dot(tri.e1, p);
        if (det == 0.0f) return false; // the ray runs in the triangle's plane
        const float inverse = 1.0f / det;
        const glm::vec3 s = ray.origin - tri.v0;
        u = glm::dot(s, p) * inverse;
        if (!(u >= 0.0f && u <= 1.0f)) return false;
        const glm::vec3 q = glm::cross(s, tri.e1);
        v = glm::dot(ray.direction, q) * inverse;
        if (!(v >= 0.0f && u + v <= 1.0f)) return false;
        t = glm::dot(tri.e2, q) * inverse;
        return t > 0.0f && t < tMax;
    }

    PeerHit closestHit(const PeerRay& ray) const {
        PeerHit hit;
        float best = std::numeric_limits<float>::infinity(), t = 0, u = 0, v = 0;
        for (std::uint32_t k = 0; k < spheres->size(); ++k) {
            if (hitSphere(ray, (*spheres)[k], best, t)) {
                best = t;
                hit = {t, HitKind::sphere, k, 0.0f, 0.0f};
            }
        }
        for (std::uint32_t k = 0; k < triangles.size(); ++k) {
            if (hitTriangle(ray, triangles[k], best, t, u, v)) {
                best = t;
                hit = {t, HitKind::triangle, k, u, v};
            }
        }
        return hit;
    }

    bool occluded(const PeerRay& ray, float tMax) const {
        float t = 0, u = 0, v = 0;
        for (const glm::vec4& sphere : *spheres)
            if (hitSphere(ray, sphere, tMax, t)) return true;
        for (const EdgeTriangle& tri : triangles)
            if (hitTriangle(ray, tri, tMax, t, u, v)) return true;
        return false;
    }

    // No per-thread state: every thread shares the one read-only loop.
    const BruteForce& worker() const { return *this; }
};

PeerRenderer makeBruteForce(const PeerScene& scene, const PeerOptions& options) {
    auto brute = std::make_shared<BruteForce>();
    brute->spheres = &scene.spheres;
    brute->triangles.reserve(scene.triangles.size());
    for (const glm::uvec3& ids : scene.triangles) {
        const glm::vec3 a = scene.positions[ids.x];
        brute->triangles.push_back({a, scene.positions[ids.y] - a, scene.positions[ids.z] - a});
    }
    PeerRenderer peer;
    peer.device = "brute force, " + threadCount(options.threads);
    peer.memoryBytes = peerSceneBytes(scene) + brute->triangles.size() * sizeof(EdgeTriangle);
    peer.renderFrame = [brute, &scene, options](Image8& image) {
        return renderImage(scene, *brute, options.render, options.threads, image);
    };
    return peer;
}

} // namespace

int main(int argc, char** argv) {
    return runPeer(argc, argv, "brute_force_peer", makeBruteForce);
}
