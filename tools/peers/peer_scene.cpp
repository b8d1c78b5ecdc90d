#include "peer_scene.h"

#include "scene/scene_triangles.h"

#include <bit>
#include <functional>
#include <unordered_map>

namespace {

PeerMaterial toFloat(const Material& m) {
    return {glm::vec3(m.diffuse), glm::vec3(m.specular), float(m.shininess),
            glm::vec3(mirrorWeight(m))};
}

// A position's bit pattern as a hash key: equal floats share one vertex (-0 and 0 stay
// apart, which costs a duplicate at worst).
struct PositionKey {
    std::uint32_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        std::uint64_t h = k.x;
        h = h * 0x9E3779B97F4A7C15ull ^ k.y;
        h = h * 0x9E3779B97F4A7C15ull ^ k.z;
        return std::size_t(h ^ (h >> 29));
    }
};

} // namespace

PeerScene makePeerScene(const Scene& scene) {
    PeerScene out;
    out.ambient = glm::vec3(scene.ambient);
    for (const Sphere& s : scene.spheres) {
        out.spheres.emplace_back(glm::vec3(s.center), float(s.radius));
        out.sphereMaterials.push_back(toFloat(s.material));
    }
    for (const Light& l : scene.lights)
        out.lights.push_back({glm::vec3(l.position), glm::vec3(l.color)});

    out.fileTriangles = triangleCount(scene);
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> index;
    index.reserve(out.fileTriangles * 2);
    forEachTriangle(scene, [&](const Triangle& t) {
        const Vertex* v = t.vertices;
        // Zero area decided in double, as the reference does, so both skip the same ones.
        if (glm::cross(v[1].position - v[0].position, v[2].position - v[0].position) ==
            glm::dvec3(0.0))
            return;
        glm::uvec3 ids;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 p(v[k].position);
            const PositionKey key{std::bit_cast<std::uint32_t>(p.x),
                                  std::bit_cast<std::uint32_t>(p.y),
                                  std::bit_cast<std::uint32_t>(p.z)};
            const auto [it, added] = index.try_emplace(key, std::uint32_t(out.positions.size()));
            if (added) out.positions.push_back(p);
            ids[k] = it->second;
            out.corners.push_back({glm::vec3(v[k].normal), toFloat(v[k].material)});
        }
        out.triangles.push_back(ids);
    });
    return out;
}

std::size_t peerSceneBytes(const PeerScene& s) {
    return s.spheres.size() * sizeof(glm::vec4) + s.sphereMaterials.size() * sizeof(PeerMaterial) +
           s.positions.size() * sizeof(glm::vec3) + s.triangles.size() * sizeof(glm::uvec3) +
           s.corners.size() * sizeof(PeerCorner) + s.lights.size() * sizeof(PeerLight);
}
