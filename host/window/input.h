// The window's keys and mouse (docs/window.md): GLFW callbacks that turn input
// into camera moves, reloads, a screenshot request or vsync.
#pragma once

#include "window/viewer.h"

#include <string>

// Points the window's GLFW callbacks at viewer (also the window's user pointer).
void installInputCallbacks(Viewer& viewer);

// W/A/S/D (or the arrow keys), Space and Left Ctrl held down: fly at a speed that crosses the scene
// in about four seconds. Returns whether one is held (the loop then keeps polling).
bool applyFlyKeys(Viewer& viewer);

// The current camera as exact command-line options ("--camera-pos X,Y,Z --camera-target ...
// --camera-up ... --fov DEG"): what O prints and the overlay shows.
std::string cameraOptions(const Viewer& viewer);
