// How long each phase of the start-up took (reading the file, making the model a scene,
// packing, the hierarchy, the upload, the kernel), for --bench's phases_ms: a process-wide
// record, since the phases run in different layers. A phase timed twice adds up.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

// Adds milliseconds to the phase `name`; safe from any thread.
void recordPhase(const std::string& name, double milliseconds);

// Every phase recorded so far, in the order each was first recorded, with its total.
std::vector<std::pair<std::string, double>> recordedPhases();

// Times its own lifetime as the phase `name`.
class PhaseTimer {
  public:
    explicit PhaseTimer(std::string name)
        : name_(std::move(name)), start_(std::chrono::steady_clock::now()) {}
    ~PhaseTimer() {
        recordPhase(name_, std::chrono::duration<double, std::milli>(
                               std::chrono::steady_clock::now() - start_)
                               .count());
    }
    PhaseTimer(const PhaseTimer&) = delete;
    PhaseTimer& operator=(const PhaseTimer&) = delete;

  private:
    std::string name_;
    std::chrono::steady_clock::time_point start_;
};
