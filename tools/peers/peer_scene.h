// The scene as the CPU peers use it: the file's scene in float, triangles indexing one
// shared vertex buffer (what Embree wants), shading data per triangle corner.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

struct PeerMaterial {
    glm::vec3 kd{0.0f};
    glm::vec3 ks{0.0f};
    float shininess = 0.0f;
    glm::vec3 kr{0.0f}; // the mirror weight: ks times the mirror share
};

// One corner of a triangle: what shading interpolates with the barycentrics.
struct PeerCorner {
    glm::vec3 normal{0.0f}; // as the file gives it (maybe unnormalised or zero)
    PeerMaterial material;
};

struct PeerLight {
    glm::vec3 position{0.0f};
    glm::vec3 color{0.0f};
};

struct PeerScene {
    glm::vec3 ambient{0.0f};
    std::vector<glm::vec4> spheres; // centre in xyz, radius in w
    std::vector<PeerMaterial> sphereMaterials;
    std::vector<glm::vec3> positions;  // distinct vertex positions
    std::vector<glm::uvec3> triangles; // indices into positions; zero-area ones dropped
    std::vector<PeerCorner> corners;   // 3 per kept triangle, in vertex order
    std::vector<PeerLight> lights;
    std::size_t fileTriangles = 0; // as in the file, zero-area ones included
};

// Rounds to float, shares identical positions, drops triangles of zero area (no ray
// can hit them; the parser has warned about them), like the reference does.
PeerScene makePeerScene(const Scene& scene);

// Bytes of the arrays above: the scene data a peer holds besides its own structures.
std::size_t peerSceneBytes(const PeerScene& scene);
