// What the window writes out: the P and Shift+P screenshots and the --bench-window report.
#pragma once

#include "window/viewer.h"

// Writes the output image as it stands (viewer.samplesDone samples per pixel) to the next
// SCENE-screenshot-N-Sspp.png in the current folder and prints the headless command that
// renders the same image; clears both screenshot requests.
void writeScreenshot(Viewer& viewer);

// The window is closing: says that a Shift+P request still waiting was dropped, and the
// headless command that renders what it waited for.
void dropPendingScreenshot(const Viewer& viewer);

// --bench-window: counts a traced frame of samples per pixel; the first only starts the clock.
void countBenchFrame(Viewer& viewer, std::uint32_t samples);

// --bench-window: once N frames after the first are done, prints one JSON line and ends.
void finishBenchIfDone(Viewer& viewer);
