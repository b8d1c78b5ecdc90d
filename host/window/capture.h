// What the window writes out: the P key's screenshot and the --bench-window report.
#pragma once

#include "window/viewer.h"

// Writes the output image to the next SCENE-screenshot-N.png in the current folder and
// prints the headless command that renders the same image.
void writeScreenshot(Viewer& viewer);

// --bench-window: counts a traced frame of samples per pixel; the first only starts the clock.
void countBenchFrame(Viewer& viewer, std::uint32_t samples);

// --bench-window: once N frames after the first are done, prints one JSON line and ends.
void finishBenchIfDone(Viewer& viewer);
