// Settings of Mesa's CPU Vulkan driver (lavapipe) for this process. lavapipe reads them from
// the environment when the instance first lists its device, so they are set before any
// Vulkan call; a GPU driver never reads them.
#pragma once

#include <cstdint>

// --threads N: lavapipe's worker threads (LP_NUM_THREADS; its default is one per core, and
// it clamps to its own maximum). 0 leaves the environment as it is.
void requestCpuDriverThreads(std::uint32_t threads);

// What requestCpuDriverThreads asked for (0: nothing), so that choosing a GPU can say that
// the request has no effect there.
std::uint32_t requestedCpuDriverThreads();
