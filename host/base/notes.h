// Informational lines on stderr (the device chosen, the scene's memory, progress, "Wrote
// FILE", warnings): --quiet turns them all off. Errors, and the validation layer's
// messages, are not notes: they always print.
#pragma once

// Set once, from the command line, before anything prints a note.
void setQuiet(bool quiet);
bool quiet();

// printf to stderr, unless quiet.
[[gnu::format(printf, 1, 2)]] void note(const char* format, ...);
