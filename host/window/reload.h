// Hot reload: the scene file and --shader-dir are watched; a save (or the R key) builds
// the renderer anew, and a scene or shader that fails keeps the last good one on screen.
#pragma once

#include "window/viewer.h"

// How often the scene file and --shader-dir are checked for a save (seconds); also how
// long an idle window sleeps between looks.
constexpr double kWatchInterval = 0.25;

// Loads the scene file again and recompiles the shaders with it; a parse or compile error
// is printed and the last good scene and kernel stay.
void reloadScene(Viewer& viewer);

// At most every kWatchInterval: reloads what was saved since the last look.
void pollWatchedFiles(Viewer& viewer);

// The overlay's switches: options with other kernel choices, depth, acceleration or sample
// target, applied as the command line would apply them (a renderer built anew from them);
// refinement restarts. Returns false, keeping the last good kernel, when it cannot be built.
bool applyOptions(Viewer& viewer, const Options& options);
