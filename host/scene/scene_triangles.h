// Every triangle of a scene, numbered one way: the scene file's own (Scene::triangles)
// first, then each mesh's in order. For the code that looks at triangles one at a time in
// the scene format's per-vertex form (the reference, --save-scene, --check, the peers);
// the packer reads meshes as they are.
#pragma once

#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

std::size_t triangleCount(const Scene& scene);

// Triangle t of mesh, each vertex with its position, normal and material (cornerMaterial).
Triangle meshTriangle(const Mesh& mesh, std::size_t t);

// Triangle `index` in the numbering above; throws std::out_of_range past the last.
Triangle triangleAt(const Scene& scene, std::size_t index);

// A triangle's texture and its corners' texture coordinates: a model's triangle whose
// material has a texture (the corners' material.diffuse then multiplies its colour, mesh.h).
// Kept apart from Triangle, which every triangle of a scene file pays for.
struct TriangleTexturing {
    std::uint32_t texture = 0; // Scene::textures' index
    glm::dvec2 texcoords[3];
};

// Triangle `index`'s texturing in the numbering above, if it has any; throws
// std::out_of_range past the last triangle.
std::optional<TriangleTexturing> triangleTexturingAt(const Scene& scene, std::size_t index);

// Every triangle's line in its file, in the numbering above.
std::vector<std::int64_t> triangleLines(const Scene& scene);

// Calls visit(triangle) for every triangle in the numbering above.
template <typename Visit> void forEachTriangle(const Scene& scene, Visit&& visit) {
    for (const Triangle& triangle : scene.triangles)
        visit(triangle);
    for (const Mesh& mesh : scene.meshes)
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            visit(meshTriangle(mesh, t));
}
