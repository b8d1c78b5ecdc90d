// The window's keys and mouse: each GLFW callback finds the Viewer through the window's
// user pointer and turns the input into a camera move, a reload, a screenshot request or
// a vsync toggle. The camera math itself is in scene/camera.cpp (no GLFW there).
// host/cli/window_keys.h describes these keys and gestures to the user; a test checks that
// the keys named here are exactly the ones it lists.
#include "window/input.h"

#include "window/compare_view.h"
#include "window/overlay.h"
#include "window/reload.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <string>

namespace {

// Mouse sensitivity (radians per pixel) for orbit and look.
constexpr double kOrbitPerPixel = 0.01, kLookPerPixel = 0.003;

Viewer& viewerOf(GLFWwindow* window) {
    return *static_cast<Viewer*>(glfwGetWindowUserPointer(window));
}

// Orbit and dolly turn around a target at the scene's depth rather than the default one
// unit ahead. Placed on the first such move only, so that the pose of --camera-pos (and
// of the default camera) is used unchanged, bit for bit, until the user moves.
void placePivot(Viewer& viewer) {
    if (viewer.pivotPlaced) return;
    viewer.pivotPlaced = true;
    viewer.camera =
        pivotAtScene(viewer.camera, viewer.bounds, std::max(viewer.bounds.radius, 1.0) * 1e-3);
}

void toggleVsync(Viewer& viewer) {
    viewer.vsync = !viewer.vsync;
    viewer.swapchainStale = true; // the loop recreates it with the new present mode
}

// The shortest text that reads back as exactly this double (0.2, not 0.20000000000000001).
std::string shortest(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

std::string triple(glm::dvec3 v) {
    return shortest(v.x) + "," + shortest(v.y) + "," + shortest(v.z);
}

// O: the current view as command-line options, exact, to paste into a headless command.
void printCameraOptions(const Viewer& viewer) {
    std::fprintf(stderr, "Camera: %s\n", cameraOptions(viewer).c_str());
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (action != GLFW_PRESS) return;
    Viewer& viewer = viewerOf(window);
    if (overlayWantsKeyboard(viewer)) return; // typing into the overlay
    switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
        glfwSetWindowShouldClose(window, GLFW_TRUE);
        break;
    case GLFW_KEY_R:
        reloadScene(viewer); // also recompiles the shaders: the renderer is built anew
        break;
    case GLFW_KEY_P: // what is shown now; with Shift, the finished image of this view
        if ((mods & GLFW_MOD_SHIFT) == 0) {
            viewer.snapshotNow = true;
        } else {
            viewer.screenshotPending = true;
            viewer.screenshotViewChanged = false;
            if (refining(viewer))
                std::fprintf(stderr,
                             "Screenshot: written once all %u samples per pixel are in (%u so "
                             "far)\n",
                             viewer.sampleTarget, viewer.samplesDone);
        }
        break;
    case GLFW_KEY_O:
        printCameraOptions(viewer);
        break;
    case GLFW_KEY_V:
        toggleVsync(viewer);
        break;
    case GLFW_KEY_H:
        viewer.overlay.shown = !viewer.overlay.shown;
        viewer.presentNeeded = true;
        break;
    case GLFW_KEY_I: // after the frame: the output image is traced by then
        glfwGetCursorPos(window, &viewer.storyX, &viewer.storyY);
        viewer.storyPending = true;
        viewer.storyClicked = false;
        break;
    case GLFW_KEY_1: // with --compare: the render, the image, the difference; F flips
        showCompared(viewer, ComparedPicture::Render);
        break;
    case GLFW_KEY_2:
        showCompared(viewer, ComparedPicture::Image);
        break;
    case GLFW_KEY_3:
        showCompared(viewer, ComparedPicture::Difference);
        break;
    case GLFW_KEY_F:
        showCompared(viewer, viewer.compare.shown == ComparedPicture::Image
                                 ? ComparedPicture::Render
                                 : ComparedPicture::Image);
        break;
    case GLFW_KEY_C:
    case GLFW_KEY_HOME:
        viewer.pivotPlaced = false;
        setCamera(viewer, CameraPose{});
        break;
    default:
        break;
    }
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
    Viewer& viewer = viewerOf(window);
    glfwGetCursorPos(window, &viewer.cursorX, &viewer.cursorY);
    viewer.presentNeeded = viewer.presentNeeded || viewer.overlay.shown; // the panel reacts
    // A press on the panel is the panel's; a release always ends a drag.
    if (action == GLFW_PRESS && overlayWantsMouse(viewer)) return;
    // A left click with I held inspects the clicked pixel and starts no orbit.
    const bool inspecting = glfwGetKey(window, GLFW_KEY_I) == GLFW_PRESS;
    if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS && inspecting) {
        viewer.storyX = viewer.cursorX;
        viewer.storyY = viewer.cursorY;
        viewer.storyPending = true;
        viewer.storyClicked = true;
        return;
    }
    if (button == GLFW_MOUSE_BUTTON_LEFT) viewer.leftDrag = action == GLFW_PRESS;
    if (button == GLFW_MOUSE_BUTTON_RIGHT) viewer.rightDrag = action == GLFW_PRESS;
}

void onCursor(GLFWwindow* window, double x, double y) {
    Viewer& viewer = viewerOf(window);
    const double dx = x - viewer.cursorX, dy = y - viewer.cursorY;
    viewer.cursorX = x;
    viewer.cursorY = y;
    viewer.presentNeeded = viewer.presentNeeded || viewer.overlay.shown; // hover highlights
    if (viewer.leftDrag) {
        placePivot(viewer);
        setCamera(viewer, orbitCamera(viewer.camera, -dx * kOrbitPerPixel, dy * kOrbitPerPixel));
    } else if (viewer.rightDrag) {
        setCamera(viewer, lookCamera(viewer.camera, -dx * kLookPerPixel, -dy * kLookPerPixel));
    }
}

void onScroll(GLFWwindow* window, double, double steps) {
    Viewer& viewer = viewerOf(window);
    if (overlayWantsMouse(viewer)) return;
    placePivot(viewer);
    setCamera(viewer, dollyCamera(viewer.camera, steps));
}

void onFramebufferSize(GLFWwindow* window, int, int) {
    viewerOf(window).resized = true;
}

// The window system lost the window's contents (it was exposed): show the image again.
void onRefresh(GLFWwindow* window) {
    viewerOf(window).presentNeeded = true;
}

} // namespace

std::string cameraOptions(const Viewer& viewer) {
    const CameraPose& camera = viewer.camera;
    return "--camera-pos " + triple(camera.position) + " --camera-target " + triple(camera.target) +
           " --camera-up " + triple(camera.up) + " --fov " + shortest(viewer.options.fovDegrees);
}

void installInputCallbacks(Viewer& viewer) {
    glfwSetWindowUserPointer(viewer.window, &viewer);
    glfwSetKeyCallback(viewer.window, onKey);
    glfwSetMouseButtonCallback(viewer.window, onMouseButton);
    glfwSetCursorPosCallback(viewer.window, onCursor);
    glfwSetScrollCallback(viewer.window, onScroll);
    glfwSetFramebufferSizeCallback(viewer.window, onFramebufferSize);
    glfwSetWindowRefreshCallback(viewer.window, onRefresh);
}

bool applyFlyKeys(Viewer& viewer) {
    const Clock::time_point now = Clock::now();
    const double seconds =
        std::min(std::chrono::duration<double>(now - viewer.lastMove).count(), 0.1);
    viewer.lastMove = now;
    if (overlayWantsKeyboard(viewer)) return false; // a field of the overlay has the keys
    auto held = [&](int key) { return glfwGetKey(viewer.window, key) == GLFW_PRESS ? 1.0 : 0.0; };
    // The arrow keys move as W A S D do.
    auto either = [&](int key, int arrow) { return std::max(held(key), held(arrow)); };
    const glm::dvec3 direction(either(GLFW_KEY_D, GLFW_KEY_RIGHT) -
                                   either(GLFW_KEY_A, GLFW_KEY_LEFT),
                               held(GLFW_KEY_SPACE) - held(GLFW_KEY_LEFT_CONTROL),
                               either(GLFW_KEY_W, GLFW_KEY_UP) - either(GLFW_KEY_S, GLFW_KEY_DOWN));
    if (direction == glm::dvec3(0.0)) return false;
    const double speed = std::max(viewer.bounds.radius, 1.0) * 0.5;
    setCamera(viewer, flyCamera(viewer.camera, direction * (speed * seconds)));
    return true;
}
