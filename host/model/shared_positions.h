// A model's positions shared by their bits: STL repeats a position at every corner, and
// glTF (through assimp) wherever texture coordinates or normals part; corners at the same
// position, bit for bit, with the same colour are one position, as an OBJ file's shared `v`
// would be, so that smooth normals join them (docs/models.md).
#pragma once

#include "base/deduplicator.h"
#include "model/source_model.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

class SharedPositions {
  public:
    // Every position of model comes through add (its positions start empty).
    SharedPositions(SourceModel& model, std::size_t expectedDistinct)
        : model_(model), index_(keys_, expectedDistinct) {}

    // The index of the position with this colour (as the file gives it: a colour that is not
    // finite is none, a finite one clamped to [0, 1]), added when it is new.
    std::uint32_t add(glm::vec3 position, std::optional<glm::vec3> colour, int line) {
        const Key key{position, colour.value_or(glm::vec3(0.0f)), colour ? 1u : 0u};
        const std::size_t before = keys_.size();
        const std::uint32_t index = index_.indexOf(key);
        if (keys_.size() != before) {
            model_.positions.emplace_back(position);
            model_.positionLines.push_back(line);
            const bool finite = colour && std::isfinite(colour->x) && std::isfinite(colour->y) &&
                                std::isfinite(colour->z);
            // No colours at all until a position has one (SourceModel::colors): then none
            // for those before it.
            if (finite || !model_.colors.empty()) {
                model_.colors.resize(model_.positions.size() - 1);
                model_.colors.push_back(
                    finite ? std::optional(glm::clamp(glm::dvec3(*colour), 0.0, 1.0))
                           : std::nullopt);
            }
        }
        return index;
    }

  private:
    struct Key {
        glm::vec3 position;
        glm::vec3 colour;
        std::uint32_t coloured; // 0 or 1
    };
    SourceModel& model_;
    std::vector<Key> keys_;
    Deduplicator<Key> index_;
};
