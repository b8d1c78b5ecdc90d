#include "scene/scene_triangles.h"

#include "base/populated_memory.h"

#include <stdexcept>
#include <string>

std::size_t triangleCount(const Scene& scene) {
    std::size_t count = scene.triangles.size();
    for (const Mesh& mesh : scene.meshes)
        count += mesh.triangles.size();
    return count;
}

Triangle meshTriangle(const Mesh& mesh, std::size_t t) {
    Triangle triangle;
    triangle.line = mesh.triangleLines[t];
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.triangles[t][k];
        triangle.vertices[k] =
            Vertex{mesh.positions[v], mesh.normals[v], cornerMaterial(mesh, t, v)};
    }
    return triangle;
}

Triangle triangleAt(const Scene& scene, std::size_t index) {
    if (index < scene.triangles.size()) return scene.triangles[index];
    std::size_t first = scene.triangles.size(); // of the mesh below
    for (const Mesh& mesh : scene.meshes) {
        if (index - first < mesh.triangles.size()) return meshTriangle(mesh, index - first);
        first += mesh.triangles.size();
    }
    throw std::out_of_range("triangleAt: no triangle " + std::to_string(index) + " in a scene of " +
                            std::to_string(first));
}

std::optional<TriangleTexturing> triangleTexturingAt(const Scene& scene, std::size_t index) {
    std::size_t first = scene.triangles.size(); // of the mesh below
    if (index < first) return std::nullopt;     // a scene file's triangles have no textures
    for (const Mesh& mesh : scene.meshes) {
        if (index - first < mesh.triangles.size()) {
            const std::size_t t = index - first;
            const auto texture = triangleTexture(mesh, t);
            if (!texture) return std::nullopt;
            TriangleTexturing texturing{*texture, {}};
            for (int k = 0; k < 3; ++k)
                texturing.texcoords[k] = vertexTexcoord(mesh, mesh.triangles[t][k]);
            return texturing;
        }
        first += mesh.triangles.size();
    }
    throw std::out_of_range("triangleTexturingAt: no triangle " + std::to_string(index) +
                            " in a scene of " + std::to_string(first));
}

std::vector<std::int64_t> triangleLines(const Scene& scene) {
    std::vector<std::int64_t> lines;
    reservePopulated(lines, triangleCount(scene)); // a model's copy is one large memcpy
    for (const Triangle& triangle : scene.triangles)
        lines.push_back(triangle.line);
    for (const Mesh& mesh : scene.meshes)
        lines.insert(lines.end(), mesh.triangleLines.begin(), mesh.triangleLines.end());
    return lines;
}
