// Progress of a long headless render on stderr: on a terminal, a line redrawn in place
// ("Rendering 1500x1100: 37%") and ended with a newline; otherwise (a log, a pipe) one
// summary line at the end. A render shorter than a second shows nothing unless asked.
#pragma once

#include <chrono>
#include <cstdint>

enum class ProgressMode {
    Off,    // nothing (--bench: its frames are timed, stderr stays quiet)
    Auto,   // only for a render that runs longer than a second
    Always, // --progress: from the start, however short
};

struct Progress {
    ProgressMode mode = ProgressMode::Off;
    bool terminal = false; // stderr is a TTY: redraw in place
    std::uint32_t width = 0, height = 0;
    std::chrono::steady_clock::time_point start;
    int shownPercent = -1; // the last percentage drawn, -1 before the first
};

Progress startProgress(ProgressMode mode, std::uint32_t width, std::uint32_t height);

// fraction: the part of the frame finished, 0 to 1.
void updateProgress(Progress& progress, double fraction);

// Ends the line on a terminal, or prints the summary line elsewhere.
void finishProgress(Progress& progress, std::uint32_t submissions, double longestSubmissionMs);
