#include "base/notes.h"

#include <atomic>
#include <cstdarg>
#include <cstdio>

namespace {

// Atomic: the validation layer's callback may run on a driver thread.
std::atomic<bool> quietNotes{false};

} // namespace

void setQuiet(bool quiet) {
    quietNotes = quiet;
}

bool quiet() {
    return quietNotes;
}

void note(const char* format, ...) {
    if (quietNotes) return;
    va_list arguments;
    va_start(arguments, format);
    std::vfprintf(stderr, format, arguments);
    va_end(arguments);
}
