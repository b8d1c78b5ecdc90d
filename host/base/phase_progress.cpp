#include "base/phase_progress.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace {

std::atomic<ProgressMode> phaseMode{ProgressMode::Off};

// A phase shorter than this says nothing (in Auto mode), as a render.
constexpr double kQuietSeconds = 1.0;
// How often the reporter looks at the count.
constexpr auto kTick = std::chrono::milliseconds(100);

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

void setPhaseProgressMode(ProgressMode mode) {
    phaseMode = mode;
}

PhaseProgress::PhaseProgress(std::string what, std::uint64_t total)
    : what_(std::move(what)), total_(std::max<std::uint64_t>(total, 1)),
      progress_(startProgress(phaseMode, 0, 0)) {
    if (progress_.mode == ProgressMode::Off) return;
    reporter_ = std::thread([this] { report(); });
}

PhaseProgress::~PhaseProgress() {
    if (!reporter_.joinable()) return;
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_one();
    reporter_.join();
    const double seconds = secondsSince(progress_.start);
    if (shown_ || progress_.mode == ProgressMode::Always)
        std::fprintf(stderr,
                     progress_.terminal ? "\r%s: 100%% (%.1f s)          \n"
                                        : "%s: done in %.1f s\n",
                     what_.c_str(), seconds);
}

void PhaseProgress::report() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, kTick, [this] { return stop_; })) {
        const double elapsed = secondsSince(progress_.start);
        if (progress_.mode == ProgressMode::Auto && elapsed < kQuietSeconds) continue;
        const double fraction =
            std::min(1.0, double(done_.load(std::memory_order_relaxed)) / double(total_));
        const int percent = static_cast<int>(fraction * 100.0);
        if (progress_.terminal) {
            if (percent == progress_.shownPercent) continue;
            progress_.shownPercent = percent;
        } else if (shown_ && elapsed - progress_.lastLineSeconds < progress_.lineInterval) {
            continue;
        }
        progress_.lastLineSeconds = elapsed;
        std::fprintf(stderr, "%s%s: %d%% (%.1f s elapsed, about %.1f s left)%s",
                     progress_.terminal ? "\r" : "", what_.c_str(), percent, elapsed,
                     secondsLeft(fraction, elapsed), progress_.terminal ? "   " : "\n");
        std::fflush(stderr);
        shown_ = true;
    }
}
