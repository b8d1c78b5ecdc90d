// A model's triangles as one indexed mesh (model_scene.h): which triangles it gets, and its
// vertices, corners that agree bit for bit on position, texture coordinates and normal
// sharing one, numbered in order of first appearance. The normals a corner lacks are
// smooth_normals.h's. Shared among the host's threads where the order cannot change a bit.
#pragma once

#include "base/phase_progress.h"
#include "model/smooth_normals.h"
#include "model/source_model.h"
#include "scene/mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

// What becomes of a model's triangle: the mesh gets it, or it is left out for using a
// position far beyond the others (far_vertices.h), or as degenerate (two corners at one
// position, or no area).
enum class TriangleFate : std::uint8_t { kept, far, degenerate };

// Each triangle's fate; farFaces: the faces that use a far position (empty: none).
// positions: the model's, as turned up.
std::vector<TriangleFate> triangleFates(const SourceModel& model,
                                        const std::vector<glm::dvec3>& positions,
                                        const std::vector<bool>& farFaces);

// Where a vertex goes: its position placed, its normal turned with the model.
struct VertexPlacement {
    std::function<glm::dvec3(const glm::dvec3&)> place, turn;
};

// Whether a kept triangle has a corner without a normal: the model then needs its smooth
// normals.
bool needsSmoothNormals(const SourceModel& model, const std::vector<TriangleFate>& fates);

// The kept triangles as a mesh (its materials not set): positions and normals as turned up;
// smooth: the model's smooth normals when it needs them (needsSmoothNormals), released
// once the corners have their normals, before the vertices' arrays are filled.
Mesh modelMesh(const SourceModel& model, const std::vector<glm::dvec3>& positions,
               const std::vector<glm::dvec3>& normals, const std::vector<TriangleFate>& fates,
               std::optional<SmoothNormals> smooth, const VertexPlacement& placement,
               PhaseProgress* progress = nullptr);
