#include "render/interrupt.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <string>

namespace {

// Lock-free, so the handler may store to it (async-signal-safe).
std::atomic<int> receivedSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onSignal(int signalNumber) {
    receivedSignal.store(signalNumber);
}

} // namespace

Interrupted::Interrupted(int number)
    : std::runtime_error(std::string("interrupted by ") +
                         (number == SIGINT ? "SIGINT (Ctrl-C)" : "SIGTERM") +
                         ": stopped after the current submission, nothing written"),
      signalNumber(number) {}

void installInterruptHandlers() {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND; // the second Ctrl-C is not caught: it ends the process
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int interruptSignal() {
    return receivedSignal.load();
}

void throwIfInterrupted() {
    if (int number = receivedSignal.load()) throw Interrupted(number);
}
