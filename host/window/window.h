// The interactive window: GLFW, a swapchain, and the same trace as the headless path.
#pragma once

#include "cli/options.h"
#include "compare/comparison.h"
#include "scene/scene.h"

#include <string>

// Shows the scene until the user closes the window. Returns false, having shown
// nothing, when no window system is available (no display): the caller then
// renders headless instead. With a comparison (--compare), keys show its image and
// difference in place of the render, and I prints a pixel's diagnosis.
bool runWindow(const Options& options, const Scene& scene, const Comparison* comparison = nullptr);

// Why the last runWindow returned false: GLFW's message, e.g. that DISPLAY is missing.
std::string windowUnavailableReason();
