// The normals a model's corners get when its file gives none (docs/models.md): for face f
// and its position p, the normalised sum of the Newell normals of the faces around p (each
// face once, in file order) whose unit normal is within the crease angle of f's, f itself
// always included. The same arithmetic as tools/obj_to_scene.py's, operation for operation.
#pragma once

#include "base/keyed_lists.h"
#include "model/source_model.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

class SmoothNormals {
  public:
    // positions: the model's, as turned up; faces left out of the scene (leftOut[f], or
    // none when it is empty) count for no corner.
    SmoothNormals(const SourceModel& model, const std::vector<glm::dvec3>& positions,
                  double creaseDegrees, const std::vector<bool>& leftOut);

    glm::dvec3 at(std::uint32_t face, std::uint32_t position) const;

  private:
    // Whether face other's unit normal is within the crease angle of face's (symmetric).
    bool withinCrease(std::uint32_t face, std::uint32_t other) const;
    // Whether every two faces around position are within the crease angle of each other:
    // then at gives each of them the same normal, sumAround's.
    bool allWithinCrease(std::uint32_t position) const;
    // The normalised sum of the Newell normals of every face around position, in order.
    glm::dvec3 sumAround(std::uint32_t position) const;

    double cosine_;
    bool everywhere_;
    std::vector<glm::dvec3> newell_; // per face
    // Per face, its unit normal rounded to float, for the crease test (smooth_normals.cpp):
    // 12 bytes a face rather than 24.
    std::vector<glm::vec3> unit_;
    // The faces around each position, in file order.
    KeyedLists facesAt_;
    // Per position: whether allWithinCrease, and then its faces' normal.
    std::vector<std::uint8_t> shared_;
    std::vector<glm::dvec3> sharedNormal_;
};
