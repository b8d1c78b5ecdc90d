// The interactive window: GLFW, a swapchain, and the same trace as the headless path.
#pragma once

#include "options.h"
#include "scene.h"

// Shows the scene until the user closes the window. Returns false, having shown
// nothing, when no window system is available (no display): the caller then
// renders headless instead.
bool runWindow(const Options& options, const Scene& scene);
