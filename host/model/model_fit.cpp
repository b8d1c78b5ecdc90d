// The fit's arithmetic is the same, operation for operation, as tools/obj_to_scene.py's, so
// that both place a model at the same bits.
#include "model/model_fit.h"

#include "base/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// The distance straight ahead of the default camera at which the outermost of the turned
// positions lies `share` of the way from the centre of the view to its edge:
// y / (distance - z) = share * tanY, and x the same with tanX.
double distanceForShare(const std::vector<glm::dvec3>& turned, double tanY, double tanX,
                        double share) {
    const double vertical = share * tanY, horizontal = share * tanX;
    double distance = 0.0;
    for (const glm::dvec3& v : turned)
        distance = std::max(distance,
                            v.z + std::max(std::abs(v.y) / vertical, std::abs(v.x) / horizontal));
    return distance;
}

// The silhouette's extent in shares of the frame, over some of the positions.
struct Silhouette {
    double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
    bool behind = false; // a position not in front of the eye
};

// Half the larger of the silhouette's width and height as shares of the frame's, the model's
// centre at distance straight ahead; infinite when a position is not in front of the eye.
// Found on all threads: minima and maxima are the same in any order.
double halfSpan(const std::vector<glm::dvec3>& turned, double tanY, double tanX, double distance) {
    const std::vector<IndexRange> ranges = splitRange(turned.size(), 16384);
    std::vector<Silhouette> parts(ranges.size());
    parallelFor(ranges.size(), [&](std::size_t k) {
        Silhouette& part = parts[k];
        for (std::size_t i = ranges[k].begin; i < ranges[k].end; ++i) {
            const glm::dvec3& v = turned[i];
            const double depth = distance - v.z;
            if (!(depth > 0.0)) {
                part.behind = true;
                return;
            }
            const double x = v.x / (depth * tanX), y = v.y / (depth * tanY);
            part.left = std::min(part.left, x);
            part.right = std::max(part.right, x);
            part.bottom = std::min(part.bottom, y);
            part.top = std::max(part.top, y);
        }
    });
    Silhouette all;
    for (const Silhouette& part : parts) {
        if (part.behind) return std::numeric_limits<double>::infinity();
        all.left = std::min(all.left, part.left);
        all.right = std::max(all.right, part.right);
        all.bottom = std::min(all.bottom, part.bottom);
        all.top = std::max(all.top, part.top);
    }
    return std::max(all.right - all.left, all.top - all.bottom) / 2.0;
}

constexpr int kFitSteps = 40;

} // namespace

// How far straight ahead the fitted model goes: where its silhouette spans kFrameShare of
// the frame's width or height (the larger share), found by bisection, but no nearer than
// where its outermost position lies kFrameLimit of the way to the frame's edge. A model
// seen face on is symmetric, so its outermost positions decide (80% of the frame); one seen
// along its length has a near end larger than its far end, and comes nearer, up to the
// limit, until the span is 80%.
double fitDistance(const std::vector<glm::dvec3>& turned, double tanY, double tanX) {
    double nearest = distanceForShare(turned, tanY, tanX, kFrameLimit);
    double farthest = distanceForShare(turned, tanY, tanX, kFrameShare); // spans <= the share
    if (halfSpan(turned, tanY, tanX, nearest) <= kFrameShare) return nearest;
    for (int step = 0; step < kFitSteps; ++step) {
        const double middle = (nearest + farthest) / 2.0;
        if (halfSpan(turned, tanY, tanX, middle) > kFrameShare)
            nearest = middle;
        else
            farthest = middle;
    }
    return farthest;
}

CameraPose refitCamera(const CameraPose& pose, const std::vector<glm::dvec3>& positions,
                       double fovDegrees, double aspect) {
    if (positions.empty()) return pose;
    const CameraBasis basis = cameraBasis(pose);
    std::vector<glm::dvec3> turned;
    turned.reserve(positions.size());
    for (const glm::dvec3& p : positions) {
        const glm::dvec3 d = p - pose.target;
        turned.emplace_back(glm::dot(d, basis.right), glm::dot(d, basis.up),
                            -glm::dot(d, basis.forward));
    }
    const double tanY = std::tan(fovDegrees * (M_PI / 180.0) / 2.0);
    const double distance = fitDistance(turned, tanY, tanY * aspect);
    if (!std::isfinite(distance) || !(distance > 0.0)) return pose;
    CameraPose refitted = pose;
    refitted.position = pose.target - basis.forward * distance;
    return refitted;
}
