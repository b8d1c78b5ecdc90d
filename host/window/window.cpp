// The interactive window: a progressive view. While nothing changes, every frame adds a
// few samples per pixel to a running sum (GpuFrameParams.dispatch) and shows their average,
// up to --spp N (then the image is exactly the headless --spp N render) or kSampleCap.
// A change (camera, size, a saved scene file or shader) starts the sum again. A window
// with nothing left to do sleeps in glfwWaitEventsTimeout, waking to poll the files.
//
// This file opens the window and its Vulkan objects, runs the frame loop and closes it
// all again. The loop's pieces: input (keys, mouse), present (trace, blit,
// present), reload (hot reload), capture (screenshot, --bench-window), overlay (ImGui);
// viewer.h holds the state they share.
#include "window/window.h"

#include "base/scope_guard.h"
#include "cli/render_settings.h"
#include "cli/window_keys.h"
#include "gpu/vk_check.h"
#include "window/capture.h"
#include "window/compare_view.h"
#include "window/input.h"
#include "window/overlay.h"
#include "window/present.h"
#include "window/reload.h"
#include "window/story.h"
#include "window/viewer.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

// Refinement stops here without --spp: the image no longer changes visibly, and an idle
// window should not keep a CPU device busy for ever.
constexpr std::uint32_t kSampleCap = 1024;

// GLFW reports its errors through a callback. Before glfwInit succeeds they only say
// that there is no display, which the caller handles by rendering headless; after it,
// every error is worth printing.
bool glfwReady = false;
std::string glfwInitError; // the last error before glfwInit succeeded

void onGlfwError(int code, const char* description) {
    if (glfwReady)
        std::fprintf(stderr, "GLFW error 0x%x: %s\n", code, description);
    else
        glfwInitError = description;
}

void open(Viewer& viewer, const Options& commandLine, const Scene& scene,
          const Comparison* comparison) {
    viewer.options = commandLine;
    const Options& options = viewer.options;
    viewer.scene = scene;
    viewer.camera = cameraFor(options, scene);
    // The pivot and the fly speed come from what the camera is there to see, not from a
    // floor that reaches a hundred model sizes away.
    viewer.bounds = subjectBounds(scene, viewer.camera, options.fovDegrees,
                                  double(options.width) / double(options.height));
    viewer.sceneName = options.scenePath.filename().string();
    viewer.continuous = options.redrawContinuously;
    viewer.benchFrames = options.benchWindowFrames;
    // The bench times the view at one sample per frame, without waiting for the display.
    viewer.sampleTarget = options.samplesGiven ? options.samplesPerPixel : kSampleCap;
    if (viewer.benchFrames > 0) {
        viewer.sampleTarget = std::max(viewer.sampleTarget, viewer.benchFrames + 1);
        viewer.vsync = false;
    }
    viewer.snapshotCounts = options.snapshotCounts;
    viewer.overlay.shown = options.overlay;
    viewer.sceneWatch = watchPath(options.scenePath);
    if (!options.shaderDirectory.empty()) viewer.shaderWatch = watchPath(options.shaderDirectory);

    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan presents; no OpenGL context
    glfwWindowHintString(GLFW_X11_CLASS_NAME, "Raytracer");
    glfwWindowHintString(GLFW_X11_INSTANCE_NAME, "raytracer");
    std::string title = viewer.sceneName + " - rendering...";
    viewer.window =
        glfwCreateWindow(int(options.width), int(options.height), title.c_str(), nullptr, nullptr);
    if (!viewer.window)
        throw std::runtime_error("could not create a window (see the GLFW error above)");
    installInputCallbacks(viewer);

    if (!glfwVulkanSupported())
        throw std::runtime_error("GLFW found no Vulkan loader for the window");
    std::uint32_t extensionCount = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
    if (!extensions) throw std::runtime_error("Vulkan cannot present to this window system");
    createInstance(viewer.context, {extensions, extensions + extensionCount}, options.validate);
    VK_CHECK(
        glfwCreateWindowSurface(viewer.context.instance, viewer.window, nullptr, &viewer.surface));
    createDevice(viewer.context, options.device, viewer.surface,
                 options.kernel.precision == Precision::Fp64);

    // The output starts at the requested size; the first swapchain adjusts it to the
    // framebuffer's size, should the window system have chosen another. The window's own
    // choices: its sample target and a running sum refined frame by frame.
    RenderSettings settings = renderSettingsFrom(options);
    settings.samplesPerPixel = viewer.sampleTarget;
    settings.camera = viewer.camera;
    settings.terminatorFix = terminatorFixFor(options, scene);
    settings.progressive = true;
    createRenderer(viewer.renderer, viewer.context, scene, settings);
    createFrames(viewer);
    viewer.compare.comparison = comparison;
    openCompareView(viewer);
}

void runLoop(Viewer& viewer) {
    while (!glfwWindowShouldClose(viewer.window)) {
        if (viewer.continuous) {
            restartRefinement(viewer);
            viewer.presentNeeded = true;
        }
        // Sleep until something happens, or the next look at the files, unless a frame
        // is still owed or the user is flying.
        const bool busy = viewer.presentNeeded || viewer.swapchainStale || viewer.resized ||
                          refining(viewer) || viewer.leftDrag || viewer.rightDrag;
        if (busy)
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(kWatchInterval);
        if (glfwWindowShouldClose(viewer.window)) break;
        pollWatchedFiles(viewer);
        if (applyFlyKeys(viewer)) viewer.presentNeeded = true;
        if (viewer.resized) {
            viewer.resized = false;
            viewer.swapchainStale = true;
        }
        if (viewer.swapchainStale && !refreshSwapchain(viewer)) {
            glfwWaitEventsTimeout(
                kWatchInterval); // minimised: draw nothing until the window changes
            continue;
        }
        placeRigForCamera(viewer); // before the trace that sees the new camera
        if (viewer.presentNeeded || refining(viewer)) drawFrame(viewer);
        if (viewer.storyPending) printStoryUnderCursor(viewer); // the image is traced by now
        if (viewer.snapshotNow ||
            (viewer.screenshotPending && !refining(viewer) && !viewer.continuous))
            writeScreenshot(viewer);
        finishBenchIfDone(viewer);
    }
}

// Everything in reverse order of creation, once the device is idle. Safe on a
// partly opened viewer. The surface goes before the device here only because
// destroyContext removes device and instance together; its swapchain is gone by then.
void close(Viewer& viewer) {
    if (viewer.context.device) vkDeviceWaitIdle(viewer.context.device);
    destroyOverlay(viewer);
    destroyCompareView(viewer);
    destroyFrames(viewer);
    destroySwapchain(viewer.swapchain, viewer.context);
    destroyRenderer(viewer.renderer, viewer.context);
    if (viewer.surface) vkDestroySurfaceKHR(viewer.context.instance, viewer.surface, nullptr);
    viewer.surface = VK_NULL_HANDLE;
    destroyContext(viewer.context);
    if (viewer.window) glfwDestroyWindow(viewer.window);
    viewer.window = nullptr;
}

// The viewer, then GLFW itself: after a quit and after an exception alike.
void shutDown(Viewer& viewer) {
    close(viewer);
    glfwReady = false;
    glfwTerminate();
}

} // namespace

std::string windowUnavailableReason() {
    return glfwInitError.empty() ? "GLFW could not start" : glfwInitError;
}

bool runWindow(const Options& options, const Scene& scene, const Comparison* comparison) {
    glfwSetErrorCallback(onGlfwError);
    glfwInitError.clear();
    if (!glfwInit()) return false; // no display: the caller renders headless
    glfwReady = true;
    Viewer viewer;
    ScopeExit closeAll([&] { shutDown(viewer); });
    open(viewer, options, scene, comparison);
    std::fputs(windowKeysLine().c_str(), stderr);
    runLoop(viewer);
    dropPendingScreenshot(viewer);
    return true;
}
