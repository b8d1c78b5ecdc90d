// Progress of a long headless render on stderr. On a terminal, a line redrawn in place
// ("Rendering 1500x1100: 37% (3.1 s elapsed, about 5.3 s left)") and ended with a newline;
// otherwise (a log, a pipe) a plain line every few seconds ("progress: 37% 3.1 s elapsed,
// about 5.3 s left") and one summary line at the end. A render shorter than a second
// shows nothing unless asked (--progress).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

enum class ProgressMode {
    Off,    // nothing (--bench: its frames are timed, stderr stays quiet; --quiet)
    Auto,   // only for a render that runs longer than a second
    Always, // --progress: from the start, however short
};

// Seconds between the plain lines when stderr is not a terminal; the environment variable
// RAYTRACER_PROGRESS_INTERVAL (seconds, 0 or more) sets another, for the tests.
inline constexpr double kPlainLineSeconds = 5.0;

struct Progress {
    ProgressMode mode = ProgressMode::Off;
    bool terminal = false; // stderr is a TTY: redraw in place
    std::uint32_t width = 0, height = 0;
    std::chrono::steady_clock::time_point start;
    int shownPercent = -1; // the last percentage drawn, -1 before the first
    double lineInterval = kPlainLineSeconds;
    double lastLineSeconds = 0; // when the last plain line was printed, from start
};

Progress startProgress(ProgressMode mode, std::uint32_t width, std::uint32_t height);

// fraction: the part of the frame finished, 0 to 1.
void updateProgress(Progress& progress, double fraction);

// Ends the line on a terminal, or prints the summary line elsewhere.
void finishProgress(Progress& progress, std::uint32_t submissions, double longestSubmissionMs);

// The time left if the rest of the frame goes as fast as what is done: elapsed times the
// part left over the part done (0 when nothing is done yet: no estimate).
double secondsLeft(double fraction, double elapsedSeconds);

// The two lines, without "\r" or "\n": "Rendering WxH: P% (E s elapsed, about L s left)" and
// "progress: P% E s elapsed, about L s left"; P is the whole percent done, rounded down.
std::string terminalProgressText(std::uint32_t width, std::uint32_t height, double fraction,
                                 double elapsedSeconds);
std::string plainProgressLine(double fraction, double elapsedSeconds);
