// A model as its file states it, before anything a scene needs is added (model_scene.h):
// positions, normals, texture coordinates, faces and their materials. Every reader makes
// one: OBJ's (obj_reader.h), PLY's, STL's and assimp's; its fields follow OBJ's statements.
#pragma once

#include "model/source_triangles.h"
#include "scene/scene.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

struct SourceModel {
    std::vector<glm::dvec3> positions;
    std::vector<int> positionLines; // each position's `v` line, for messages
    // `v x y z r g b` (a common extension): the vertex's diffuse colour, clamped to [0, 1];
    // one a position, or none at all when no position has one (32 bytes a position saved).
    std::vector<std::optional<glm::dvec3>> colors;
    std::vector<glm::dvec3> normals;   // vn, as given
    std::vector<glm::dvec2> texcoords; // vt's u and v (a third value, w, is not kept)
    // Each face's position indices, whole (smooth normals are taken per polygon): face f's
    // are facePositions[faceStarts[f]] up to facePositions[faceStarts[f + 1]], in one array
    // rather than a vector per face (which cost 56 bytes a face before its indices). Both
    // left as they start when each face is its triangle (triangles.facesAreTriangles()):
    // face f's positions are then triangle f's.
    std::vector<std::uint32_t> facePositions;
    std::vector<std::size_t> faceStarts{0};
    SourceTriangles triangles;
    // materials[0] is the default one, for faces without a known material; each with the
    // diffuse texture its map_Kd names, if any (the path from the MTL file's folder).
    std::vector<MeshMaterial> materials;
    // Textures the model file holds itself (GLB's embedded images), by the name its materials
    // give them (diffuseTexture, "*0" for the first): each an image file's bytes.
    std::map<std::string, std::string> embeddedTextures;
    std::vector<std::string> warnings; // "file:line: warning: ..."
    // What the material libraries hold that the shading model does not render, for --check:
    // "texture maps (map_Kd)", "transparency (d, Tr)", "other maps (bump, map_Ks, ...)", each
    // with the number of materials that have it.
    std::map<std::string, std::size_t> notRendered;
};

inline std::size_t faceCount(const SourceModel& model) {
    return model.triangles.facesAreTriangles() ? model.triangles.size()
                                               : model.faceStarts.size() - 1;
}
inline std::span<const std::uint32_t> facePositions(const SourceModel& model, std::size_t face) {
    if (model.triangles.facesAreTriangles())
        return std::span<const std::uint32_t>(glm::value_ptr(model.triangles.positions(face)), 3);
    return std::span<const std::uint32_t>(model.facePositions)
        .subspan(model.faceStarts[face], model.faceStarts[face + 1] - model.faceStarts[face]);
}
// A face of these positions, for the readers that add faces one by one: its index, for its
// triangles, pushed next. A face of three corners must be pushed as its one triangle. The
// faces are the triangles (SourceTriangles::makeFacesTheTriangles) while every face has
// three corners; the first that has not lists the faces so far and keeps listing them.
std::uint32_t addFace(SourceModel& model, std::span<const std::uint32_t> positions);

// The number of position indices all faces hold together.
inline std::size_t facePositionCount(const SourceModel& model) {
    return model.triangles.facesAreTriangles() ? 3 * model.triangles.size()
                                               : model.facePositions.size();
}

// The material of faces that name none, or one that no material library defines, and what
// an MTL material starts from: light grey, a faint highlight and no mirror (illum 2).
inline MeshMaterial defaultModelMaterial() {
    MeshMaterial material;
    material.phong = Material{glm::dvec3(0.75), glm::dvec3(0.1), 30.0, 0.0};
    return material;
}

// The largest material library read: far beyond any real one (a few kilobytes a material).
inline constexpr std::uintmax_t kMaxMtlBytes = std::uintmax_t(64) << 20;

// Ns above this is clamped: the Phong exponent of the scene format has no use for more.
inline constexpr double kMaxModelShininess = 1000.0;
// Ns below this is raised to it: an exponent of 0 would give every lit point the full
// highlight colour; 1 is the broadest highlight that still falls off.
inline constexpr double kMinModelShininess = 1.0;
