// The fit's arithmetic is the same, operation for operation, as tools/obj_to_scene.py's, so
// that both place a model at the same bits.
#include "model/model_fit.h"

#include "base/parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace {

// Positions a thread takes at a time in the passes over all of them.
constexpr std::size_t kGrain = 1 << 15;

// The distance straight ahead of the default camera at which the outermost of the turned
// positions lies `share` of the way from the centre of the view to its edge:
// y / (distance - z) = share * tanY, and x the same with tanX.
double distanceForShare(const std::vector<glm::dvec3>& turned, double tanY, double tanX,
                        double share) {
    const double vertical = share * tanY, horizontal = share * tanX;
    return reduceRanges(
        turned.size(), kGrain,
        [&](IndexRange range) {
            double distance = 0.0;
            for (std::size_t i = range.begin; i < range.end; ++i) {
                const glm::dvec3& v = turned[i];
                distance = std::max(
                    distance, v.z + std::max(std::abs(v.y) / vertical, std::abs(v.x) / horizontal));
            }
            return distance;
        },
        [](double part, double& into) { into = std::max(into, part); });
}

// Half the larger of the silhouette's width and height as shares of the frame's, the model's
// centre at distance straight ahead; infinite when a position is not in front of the eye.
double halfSpan(const std::vector<glm::dvec3>& turned, double tanY, double tanX, double distance) {
    double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
    for (const glm::dvec3& v : turned) {
        const double depth = distance - v.z;
        if (!(depth > 0.0)) return std::numeric_limits<double>::infinity();
        const double x = v.x / (depth * tanX), y = v.y / (depth * tanY);
        left = std::min(left, x);
        right = std::max(right, x);
        bottom = std::min(bottom, y);
        top = std::max(top, y);
    }
    return std::max(right - left, top - bottom) / 2.0;
}

// The positions that can decide halfSpan at any distance, so that the bisection's forty
// steps look at a few hundred positions rather than millions, to the same bits. A position
// v with x > 0 cannot be the rightmost if another w has w.x >= v.x and w.z > v.z: w is
// nearer the eye, so w.x / (depth * tanX) >= v.x / (depth * tanX) at every distance (each
// rounding is monotone). Likewise leftwards, up and down. Positions are sorted into slices
// of z; one whose slice is below a slice holding such a w is left out. The nearest position
// stays too: it is the first to be behind the eye.
std::vector<glm::dvec3> silhouetteCandidates(const std::vector<glm::dvec3>& turned) {
    constexpr int kSlices = 4096;
    // The depth's range, and the nearest position: the first of the largest z.
    struct Depths {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        std::size_t nearest = 0;
    };
    const Depths depths = reduceRanges(
        turned.size(), kGrain,
        [&](IndexRange range) {
            Depths part;
            for (std::size_t i = range.begin; i < range.end; ++i) {
                part.low = std::min(part.low, turned[i].z);
                if (turned[i].z > part.high || i == range.begin)
                    part.high = turned[i].z, part.nearest = i;
            }
            return part;
        },
        [](const Depths& part, Depths& into) {
            into.low = std::min(into.low, part.low);
            if (part.high > into.high) into.high = part.high, into.nearest = part.nearest;
        });
    const double low = depths.low, width = depths.high - low;
    const double scale = width > 0.0 ? kSlices / width : 0.0;
    auto sliceOf = [&](const glm::dvec3& v) { // monotone in z
        const double slice = (v.z - low) * (std::isfinite(scale) ? scale : 0.0);
        return slice < kSlices - 1 ? static_cast<int>(slice) : kSlices - 1;
    };
    // How far each position reaches right, left, up and down (0 where it does not).
    auto reach = [](const glm::dvec3& v) {
        return std::array<double, 4>{std::max(v.x, 0.0), std::max(-v.x, 0.0), std::max(v.y, 0.0),
                                     std::max(-v.y, 0.0)};
    };
    // The farthest reach in each slice, then in the slices above each.
    using Reaches = std::vector<std::array<double, 4>>;
    Reaches above = reduceRanges(
        turned.size(), kGrain,
        [&](IndexRange range) {
            Reaches slices(kSlices + 1, {0.0, 0.0, 0.0, 0.0});
            for (std::size_t i = range.begin; i < range.end; ++i) {
                const std::array<double, 4> r = reach(turned[i]);
                std::array<double, 4>& slice = slices[sliceOf(turned[i])];
                for (int side = 0; side < 4; ++side)
                    slice[side] = std::max(slice[side], r[side]);
            }
            return slices;
        },
        [](const Reaches& part, Reaches& into) {
            for (std::size_t slice = 0; slice < into.size(); ++slice)
                for (int side = 0; side < 4; ++side)
                    into[slice][side] = std::max(into[slice][side], part[slice][side]);
        });
    std::array<double, 4> beyond{-1.0, -1.0, -1.0, -1.0}; // nothing above the last slice
    for (int slice = kSlices; slice-- > 0;) {
        const std::array<double, 4> own = above[slice];
        above[slice] = beyond;
        for (int side = 0; side < 4; ++side)
            beyond[side] = std::max(beyond[side], own[side]);
    }
    std::vector<glm::dvec3> candidates{turned[depths.nearest]};
    const std::vector<glm::dvec3> reaching = reduceRanges(
        turned.size(), kGrain,
        [&](IndexRange range) {
            std::vector<glm::dvec3> part;
            for (std::size_t i = range.begin; i < range.end; ++i) {
                const std::array<double, 4> r = reach(turned[i]);
                const std::array<double, 4>& higher = above[sliceOf(turned[i])];
                for (int side = 0; side < 4; ++side)
                    if (r[side] > 0.0 && r[side] > higher[side]) {
                        part.push_back(turned[i]);
                        break;
                    }
            }
            return part;
        },
        [](const std::vector<glm::dvec3>& part, std::vector<glm::dvec3>& into) {
            into.insert(into.end(), part.begin(), part.end());
        });
    candidates.insert(candidates.end(), reaching.begin(), reaching.end());
    return candidates;
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
    const std::vector<glm::dvec3> candidates = silhouetteCandidates(turned);
    if (halfSpan(candidates, tanY, tanX, nearest) <= kFrameShare) return nearest;
    for (int step = 0; step < kFitSteps; ++step) {
        const double middle = (nearest + farthest) / 2.0;
        if (halfSpan(candidates, tanY, tanX, middle) > kFrameShare)
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
