#include "base/startup_phases.h"

#include <algorithm>
#include <mutex>

namespace {

std::mutex phasesMutex;
std::vector<std::pair<std::string, double>> phases; // guarded by phasesMutex

} // namespace

void recordPhase(const std::string& name, double milliseconds) {
    const std::lock_guard lock(phasesMutex);
    const auto found = std::find_if(phases.begin(), phases.end(),
                                    [&](const auto& phase) { return phase.first == name; });
    if (found != phases.end())
        found->second += milliseconds;
    else
        phases.emplace_back(name, milliseconds);
}

std::vector<std::pair<std::string, double>> recordedPhases() {
    const std::lock_guard lock(phasesMutex);
    return phases;
}
