// Progress of a long start-up phase on stderr (reading a model, making it a scene, packing,
// building the hierarchy), as a render reports its own (progress.h): nothing for a phase
// shorter than a second unless --progress asked; on a terminal a line redrawn in place,
// "Reading knot.obj: 37% (3.1 s elapsed, about 5.3 s left)", ended with the phase's time;
// elsewhere the same line every few seconds (the renders' interval) and "Reading knot.obj:
// done in 4.2 s" at the end. A thread of its own prints, so the phase's threads only count their
// work.
#pragma once

#include "base/progress.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

// How phases report: Off under --bench and --quiet, Always under --progress, else Auto.
void setPhaseProgressMode(ProgressMode mode);

class PhaseProgress {
  public:
    // what: the phase as the line starts ("Reading knot.obj"); total: its units of work.
    PhaseProgress(std::string what, std::uint64_t total);
    ~PhaseProgress(); // the last line, if any was shown
    PhaseProgress(const PhaseProgress&) = delete;
    PhaseProgress& operator=(const PhaseProgress&) = delete;

    // Adds finished units; any thread may call it.
    void advance(std::uint64_t units) { done_.fetch_add(units, std::memory_order_relaxed); }

  private:
    void report();

    std::string what_;
    std::uint64_t total_;
    std::atomic<std::uint64_t> done_{0};
    Progress progress_; // the mode, the terminal, the start, the plain lines' interval
    bool shown_ = false;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread reporter_;
};
