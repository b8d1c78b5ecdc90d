#include "gpu/cpu_driver.h"

#include <cstdlib>
#include <string>

namespace {

std::uint32_t requestedThreads = 0;

} // namespace

void requestCpuDriverThreads(std::uint32_t threads) {
    if (threads == 0) return;
    requestedThreads = threads;
    // Overrides the variable when the user's environment also sets it: the option is the
    // more explicit of the two.
    setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
}

std::uint32_t requestedCpuDriverThreads() {
    return requestedThreads;
}
