// Far positions (far_vertices.h). tools/obj_to_scene.py's far_positions and describe_far
// do the same, operation for operation.
#include "model/far_vertices.h"

#include "base/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

} // namespace

std::vector<bool> farPositions(const std::vector<glm::dvec3>& positions) {
    const std::size_t count = positions.size(), middle = count / 2;
    std::vector<bool> far(count, false);
    if (count == 0) return far;
    glm::dvec3 median(0.0), spreads(0.0);
    parallelFor(3, [&](std::size_t axis) { // the axes on threads of their own
        std::vector<double> values(count);
        for (std::size_t i = 0; i < count; ++i)
            values[i] = positions[i][axis];
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
        median[axis] = values[middle];
        for (std::size_t i = 0; i < count; ++i)
            values[i] = std::abs(positions[i][axis] - median[axis]);
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
        spreads[axis] = values[middle];
    });
    const double spread = std::max({spreads.x, spreads.y, spreads.z});
    if (!(spread > 0.0)) return far;
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 d = glm::abs(positions[i] - median);
        far[i] = std::max({d.x, d.y, d.z}) > kFarBeyond * spread;
    }
    return far;
}

FarPositions describeFar(const SourceModel& model, const std::vector<bool>& far,
                         std::size_t trianglesLeftOut) {
    std::size_t count = 0, first = 0;
    glm::dvec3 low(0.0), high(0.0);
    bool anyNear = false;
    for (std::size_t i = 0; i < far.size(); ++i) {
        if (far[i]) {
            if (count++ == 0) first = i;
        } else {
            low = anyNear ? glm::min(low, model.positions[i]) : model.positions[i];
            high = anyNear ? glm::max(high, model.positions[i]) : model.positions[i];
            anyNear = true;
        }
    }
    const glm::dvec3 p = model.positions[first];
    std::string extent;
    for (int axis = 0; axis < 3; ++axis)
        extent += std::string(axis == 0 ? "" : ", ") + "xyz"[axis] + " " + shortNumber(low[axis]) +
                  ".." + shortNumber(high[axis]);
    return {model.positionLines[first],
            std::to_string(count) +
                " vertex(es) far beyond the rest of the model (the first here, at " +
                shortNumber(p.x) + " " + shortNumber(p.y) + " " + shortNumber(p.z) +
                ": more than " + shortNumber(kFarBeyond) +
                " times the model's spread from its median) are left out, with the faces that "
                "use them (" +
                std::to_string(trianglesLeftOut) + " triangle(s)); without them the model spans " +
                extent};
}
