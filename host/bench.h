// --bench N: timed headless frames after a warm-up, reported as one JSON line.
#pragma once

#include "cli/options.h"
#include "render/headless.h"

#include <chrono>
#include <string>

// When the process started, on the steady clock: the kernel's record of it
// (/proc/self/stat, in clock ticks of 10 ms, rounded down, so a start-up measured
// from it may read up to one tick long), so the dynamic loader's work and static
// initialisation count too. Falls back to now (call it first thing in main) where
// /proc is not available.
std::chrono::steady_clock::time_point processStartTime();

struct StartupTimes {
    std::chrono::steady_clock::time_point processStart; // processStartTime()
    double parseMs = 0;                                 // reading and parsing the scene file
};

// Renders warm-up frames, then options.benchFrames timed ones, and returns the
// JSON object of docs/performance.md ("--bench") with parse_ms, per-frame submissions, the
// process's CPU time per timed frame (cpu_ms_per_frame: the trace's cost on a CPU driver, robust to
// other load) and the kernel choices added.
std::string runBenchmark(const Context& context, Renderer& renderer, HeadlessTarget& target,
                         const Options& options, const StartupTimes& startup);
