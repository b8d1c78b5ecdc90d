#include "render/region_planner.h"

#include "shared.h"

#include <algorithm>
#include <cmath>

namespace {

// Regions are whole workgroups (except at the image's right and bottom edges), so no
// invocation of one region lands on a pixel of another.
constexpr std::uint32_t kAlignX = WORKGROUP_SIZE_X;
constexpr std::uint32_t kAlignY = WORKGROUP_SIZE_Y;

// Bounds on a region: one workgroup, and a side of 2048 (a fast GPU is then still fed
// four million pixels per submission).
constexpr double kMinPixels = double(kAlignX) * kAlignY;
constexpr double kMaxPixels = 2048.0 * 2048.0;

// Cost per pixel varies across the image (sky is cheap, a mesh is not), so the budget
// grows by at most this factor per submission: a region that lands on expensive pixels
// after cheap ones overshoots the target by a bounded amount.
constexpr double kMaxGrowth = 4.0;

std::uint32_t alignDown(double value, std::uint32_t alignment, std::uint32_t limit) {
    const double clamped = std::clamp(value, double(alignment), double(limit));
    return std::max(alignment, std::uint32_t(clamped) / alignment * alignment);
}

} // namespace

RegionPlanner createRegionPlanner(std::uint32_t fixedSide, double targetMs) {
    RegionPlanner planner;
    planner.targetMs = targetMs;
    const std::uint32_t alignment = std::max(kAlignX, kAlignY);
    if (fixedSide > 0) planner.fixedSide = (fixedSide + alignment - 1) / alignment * alignment;
    return planner;
}

void beginFrame(RegionPlanner& planner, std::uint32_t width, std::uint32_t height) {
    planner.width = width;
    planner.height = height;
    planner.x = planner.y = planner.stripHeight = 0;
}

bool nextRegion(RegionPlanner& planner, TraceRegion& region) {
    RegionPlanner& s = planner;
    if (s.y >= s.height || s.width == 0) return false;
    if (s.x == 0) {
        // A new strip: as tall as a square region of the budget.
        const std::uint32_t side =
            s.fixedSide ? s.fixedSide : alignDown(std::sqrt(s.budgetPixels), kAlignY, 2048);
        s.stripHeight = std::min(side, s.height - s.y);
    }
    // Within a strip the width follows the budget, which may have changed since the
    // strip began.
    std::uint32_t width =
        s.fixedSide ? s.fixedSide : alignDown(s.budgetPixels / s.stripHeight, kAlignX, s.width);
    // Take the rest of the strip rather than leave a region of less than half the
    // budget for last: such a sliver would cost a submission for little work.
    if (s.fixedSide == 0 && s.width - s.x < width + width / 2) width = s.width - s.x;
    width = std::min(width, s.width - s.x);
    region = {s.x, s.y, width, s.stripHeight};
    s.x += width;
    if (s.x >= s.width) {
        s.x = 0;
        s.y += s.stripHeight;
    }
    return true;
}

bool frameCovered(const RegionPlanner& planner) {
    return planner.y >= planner.height;
}

void regionTraced(RegionPlanner& planner, const TraceRegion& region, double milliseconds) {
    const double pixels = double(region.width) * region.height;
    const double wanted = pixels / std::max(milliseconds, 0.01) * planner.targetMs;
    planner.budgetPixels =
        std::clamp(wanted, kMinPixels, std::min(kMaxPixels, planner.budgetPixels * kMaxGrowth));
}
