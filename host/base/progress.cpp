#include "base/progress.h"

#include "base/notes.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>
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

// RAYTRACER_PROGRESS_INTERVAL when it is a number of seconds, else the default.
double plainLineInterval() {
    const char* text = std::getenv("RAYTRACER_PROGRESS_INTERVAL");
    if (!text) return kPlainLineSeconds;
    const std::string_view view(text);
    double seconds = 0;
    const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), seconds);
    if (error != std::errc() || end != view.data() + view.size() || !(seconds >= 0))
        return kPlainLineSeconds;
    return seconds;
}

int percentOf(double fraction) {
    return static_cast<int>(fraction * 100.0);
}

std::string figures(double fraction, double elapsedSeconds) {
    char text[96];
    std::snprintf(text, sizeof text, "%.1f s elapsed, about %.1f s left", elapsedSeconds,
                  secondsLeft(fraction, elapsedSeconds));
    return text;
}

} // namespace

double secondsLeft(double fraction, double elapsedSeconds) {
    if (fraction <= 0) return 0;
    return elapsedSeconds * (1.0 - fraction) / fraction;
}

std::string terminalProgressText(std::uint32_t width, std::uint32_t height, double fraction,
                                 double elapsedSeconds) {
    return "Rendering " + std::to_string(width) + "x" + std::to_string(height) + ": " +
           std::to_string(percentOf(fraction)) + "% (" + figures(fraction, elapsedSeconds) + ")";
}

std::string plainProgressLine(double fraction, double elapsedSeconds) {
    return "progress: " + std::to_string(percentOf(fraction)) + "% " +
           figures(fraction, elapsedSeconds);
}

Progress startProgress(ProgressMode mode, std::uint32_t width, std::uint32_t height) {
    Progress progress;
    progress.mode = quiet() ? ProgressMode::Off : mode;
    progress.terminal = isatty(STDERR_FILENO) == 1;
    progress.width = width;
    progress.height = height;
    progress.lineInterval = plainLineInterval();
    progress.start = std::chrono::steady_clock::now();
    return progress;
}

void updateProgress(Progress& progress, double fraction) {
    if (!worthShowing(progress)) return;
    const double elapsed = secondsSince(progress.start);
    if (progress.terminal) {
        const int percent = percentOf(fraction);
        if (percent == progress.shownPercent) return;
        progress.shownPercent = percent;
        // The trailing spaces wipe what a longer line before left.
        std::fprintf(
            stderr, "\r%s   ",
            terminalProgressText(progress.width, progress.height, fraction, elapsed).c_str());
        std::fflush(stderr);
        return;
    }
    // The end has its summary line instead (finishProgress).
    if (fraction >= 1.0 || elapsed - progress.lastLineSeconds < progress.lineInterval) return;
    progress.lastLineSeconds = elapsed;
    std::fprintf(stderr, "%s\n", plainProgressLine(fraction, elapsed).c_str());
}

void finishProgress(Progress& progress, std::uint32_t submissions, double longestSubmissionMs) {
    if (!worthShowing(progress)) return;
    const double seconds = secondsSince(progress.start);
    if (progress.terminal)
        std::fprintf(stderr, "\rRendering %ux%u: 100%% (%.1f s, %u submissions)          \n",
                     progress.width, progress.height, seconds, submissions);
    else
        std::fprintf(stderr, "Rendered %ux%u in %.1f s: %u submissions, the longest %.0f ms\n",
                     progress.width, progress.height, seconds, submissions, longestSubmissionMs);
    progress.mode = ProgressMode::Off;
}
