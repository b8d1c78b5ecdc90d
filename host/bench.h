// --bench N: timed headless frames after a warm-up, reported as one JSON line.
#pragma once

#include "headless.h"
#include "options.h"

#include <chrono>
#include <string>

// Renders warm-up frames, then options.benchFrames timed ones, and returns the
// JSON object of SPEC.md ("--bench"). processStart is when main() began.
std::string runBenchmark(const Context& context, const Renderer& renderer, HeadlessTarget& target,
                         const Options& options, std::chrono::steady_clock::time_point processStart);
