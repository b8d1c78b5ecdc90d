// Positions far beyond the rest of a model (an exporter's stray vertex at 1e38), found by a
// rule a stray vertex or two cannot move, and what is said of them (docs/models.md).
#pragma once

#include "model/source_model.h"

#include <cstdint>
#include <string>
#include <vector>

// Further than this many times the model's spread from its median point: far beyond it.
inline constexpr double kFarBeyond = 1000.0;

// Per position, whether it is far beyond the rest: further than kFarBeyond times the spread
// from the median point along some axis. The median and the spread (the largest, over the
// axes, of the median distance from the median coordinate) are those of the positions; a
// median of an even count is the upper of the middle two. None when the spread is 0.
std::vector<bool> farPositions(const std::vector<glm::dvec3>& positions);

// What is said of them: how many, the first one's place, the triangles left out with them,
// and the model's extent without them (in the file's coordinates); and the first one's line.
struct FarPositions {
    std::int64_t line = 0;
    std::string message;
};
FarPositions describeFar(const SourceModel& model, const std::vector<bool>& far,
                         std::size_t trianglesLeftOut);
