// Ctrl-C (SIGINT) and SIGTERM during a headless render. The handler only records the
// signal; the render loop checks between submissions and throws Interrupted, so the
// device is waited for, everything is destroyed and the temporary PNG removed before
// the process exits with 128 + the signal's number (130 for Ctrl-C).
#pragma once

#include <stdexcept>

struct Interrupted : std::runtime_error {
    explicit Interrupted(int signalNumber);
    int signalNumber;
};

// Installs the handlers. A second signal ends the process at once (default action).
void installInterruptHandlers();

// The signal received so far, or 0.
int interruptSignal();

// Throws Interrupted once a signal has arrived.
void throwIfInterrupted();
