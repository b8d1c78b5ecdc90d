// Splits a headless frame into rectangles, each traced by its own submission, sized so
// that a submission takes about kTargetSubmissionMs (kCpuTargetSubmissionMs on a CPU
// device): long enough that the cost of a submission is small beside it, short enough
// that no GPU watchdog fires and a shared GPU stays responsive however large the image
// or the sample count.
#pragma once

#include <cstdint>

// A rectangle of the output image, in pixels.
struct TraceRegion {
    std::uint32_t x = 0, y = 0, width = 0, height = 0;
};

inline constexpr double kTargetSubmissionMs = 50.0;

// On a CPU device (lavapipe) there is no GPU watchdog and no display sharing the device:
// a submission only has to end often enough for progress and Ctrl-C. Longer ones cost
// less: each submission ends with some of the device's threads idle while the last
// workgroups finish, and pays for a submit and a fence wait.
inline constexpr double kCpuTargetSubmissionMs = 400.0;

struct RegionPlanner {
    // The next region's size in pixels, learned from the last one's time; kept from
    // frame to frame. Starts small: the first region also pays for the driver's compile.
    double budgetPixels = 64.0 * 64.0;
    std::uint32_t fixedSide = 0; // > 0 (--region-size): square regions of this side, no adapting
    double targetMs = kTargetSubmissionMs; // what a region should take

    // Where the frame stands: rows are traced in strips, each strip left to right.
    std::uint32_t width = 0, height = 0;
    std::uint32_t x = 0, y = 0, stripHeight = 0;
};

// fixedSide 0 adapts toward targetMs; otherwise it is rounded up to whole workgroups.
RegionPlanner createRegionPlanner(std::uint32_t fixedSide, double targetMs = kTargetSubmissionMs);

void beginFrame(RegionPlanner& planner, std::uint32_t width, std::uint32_t height);

// The next region of the frame; false when the whole frame has been handed out.
bool nextRegion(RegionPlanner& planner, TraceRegion& region);

// True once the region last handed out was the frame's last.
bool frameCovered(const RegionPlanner& planner);

// Feeds back how long a region took, submission to fence, to size the next one.
void regionTraced(RegionPlanner& planner, const TraceRegion& region, double milliseconds);
