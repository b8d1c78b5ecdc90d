#include "render/progress.h"

#include <cstdio>
#include <unistd.h>

namespace {

// Renders quicker than this say nothing (in Auto mode): a progress line that flashes
// by is noise.
constexpr double kQuietSeconds = 1.0;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool worthShowing(const Progress& progress) {
    return progress.mode == ProgressMode::Always ||
           (progress.mode == ProgressMode::Auto && secondsSince(progress.start) > kQuietSeconds);
}

} // namespace

Progress startProgress(ProgressMode mode, std::uint32_t width, std::uint32_t height) {
    Progress progress;
    progress.mode = mode;
    progress.terminal = isatty(STDERR_FILENO) == 1;
    progress.width = width;
    progress.height = height;
    progress.start = std::chrono::steady_clock::now();
    return progress;
}

void updateProgress(Progress& progress, double fraction) {
    if (!progress.terminal || !worthShowing(progress)) return;
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == progress.shownPercent) return;
    progress.shownPercent = percent;
    std::fprintf(stderr, "\rRendering %ux%u: %d%%", progress.width, progress.height, percent);
    std::fflush(stderr);
}

void finishProgress(Progress& progress, std::uint32_t submissions, double longestSubmissionMs) {
    if (!worthShowing(progress)) return;
    const double seconds = secondsSince(progress.start);
    if (progress.terminal)
        std::fprintf(stderr, "\rRendering %ux%u: 100%% (%.1f s, %u submissions)\n", progress.width,
                     progress.height, seconds, submissions);
    else
        std::fprintf(stderr, "Rendered %ux%u in %.1f s: %u submissions, the longest %.0f ms\n",
                     progress.width, progress.height, seconds, submissions, longestSubmissionMs);
    progress.mode = ProgressMode::Off;
}
