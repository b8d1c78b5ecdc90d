// The interactive window: a progressive view. While nothing changes, every frame adds a
// few samples per pixel to a running sum (GpuFrameParams.tile) and shows their average,
// up to --spp N (then the image is exactly the headless --spp N render) or kSampleCap.
// A change (camera, size, a saved scene file or shader) starts the sum again. A window
// with nothing left to do sleeps in glfwWaitEventsTimeout, waking to poll the files.
#include "window.h"

#include "camera_controller.h"
#include "file_watch.h"
#include "pipeline_cache.h"
#include "renderer.h"
#include "screenshot.h"
#include "swapchain.h"
#include "vk_check.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

using Clock = std::chrono::steady_clock;

// Enough for a blit-only present to be recorded while the previous one still runs.
constexpr std::uint32_t kFramesInFlight = 2;
// Refinement stops here without --spp: the image no longer changes visibly, and an idle
// window should not keep a CPU device busy for ever.
constexpr std::uint32_t kSampleCap = 1024;
// Samples per frame adapt to keep a frame between these (ms): quick to react to input,
// few enough frames that presenting does not dominate.
constexpr double kFastFrameMs = 20.0, kSlowFrameMs = 60.0;
constexpr std::uint32_t kMaxSamplesPerFrame = 64;
// How often the scene file and --shader-dir are checked for a save (seconds).
constexpr double kWatchInterval = 0.25;
// Mouse sensitivity (radians per pixel) for orbit and look.
constexpr double kOrbitPerPixel = 0.01, kLookPerPixel = 0.003;

const char* const kHelpLine =
    "Window: Esc or Q quits; R reloads scene and shaders; P writes a screenshot; V toggles vsync; "
    "C or Home resets the camera; left drag orbits, wheel dollies, right drag looks, "
    "W/A/S/D and Space/Left Shift fly.\n";

// GLFW reports its errors through a callback. Before glfwInit succeeds they only say
// that there is no display, which the caller handles by rendering headless; after it,
// every error is worth printing.
bool glfwReady = false;
std::string glfwInitError; // the last error before glfwInit succeeded

void onGlfwError(int code, const char* description) {
    if (glfwReady) std::fprintf(stderr, "GLFW error 0x%x: %s\n", code, description);
    else glfwInitError = description;
}

struct Frame {
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkSemaphore imageAvailable = VK_NULL_HANDLE; // signalled by acquire, waited on by the submit
    VkFence done = VK_NULL_HANDLE;               // the submit finished; created signalled
};

struct Viewer {
    const Options* options = nullptr;
    GLFWwindow* window = nullptr;
    Context context;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    Renderer renderer;
    Swapchain swapchain;
    Frame frames[kFramesInFlight];
    std::uint32_t frameIndex = 0;
    std::string sceneName; // the title's first part
    Scene scene;           // the last scene that loaded, for shader reloads

    // Progressive refinement: samples 0..samplesDone-1 of sampleTarget are in the sum.
    std::uint32_t sampleTarget = 1;
    std::uint32_t samplesDone = 0;
    std::uint32_t samplesPerFrame = 1;
    double lastFrameMs = 0.0;
    Clock::time_point refineStart = Clock::now();

    CameraPose camera;
    bool pivotPlaced = false; // the orbit target sits at the scene's depth (see pivotAtScene)
    SceneBounds bounds;
    bool leftDrag = false, rightDrag = false;
    double cursorX = 0.0, cursorY = 0.0;
    Clock::time_point lastMove = Clock::now();

    FileWatch sceneWatch, shaderWatch;
    Clock::time_point lastWatch = Clock::now();

    bool resized = false;        // the framebuffer changed size: new swapchain, maybe a new trace
    bool swapchainStale = true;  // no usable swapchain yet, or OUT_OF_DATE/SUBOPTIMAL was reported
    bool presentNeeded = true;   // the window does not show the output image
    bool vsync = true;
    bool screenshotPending = false; // P: write it once refinement is done
    bool continuous = false;        // --redraw-continuously: restart the sum every frame (soak test)

    // --bench-window N: frames timed after the first.
    std::uint32_t benchFrames = 0, benchCounted = 0;
    std::uint64_t benchSamples = 0;
    Clock::time_point benchStart;
};

Viewer& viewerOf(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

bool refining(const Viewer& viewer) { return viewer.samplesDone < viewer.sampleTarget; }

// Something the image depends on changed: the sum starts again.
void restart(Viewer& viewer) {
    if (viewer.samplesDone != 0) viewer.refineStart = Clock::now();
    viewer.samplesDone = 0;
    viewer.samplesPerFrame = 1; // the first frame after a change comes quickly
}

void setCamera(Viewer& viewer, const CameraPose& camera) {
    viewer.camera = camera;
    setCamera(viewer.renderer, camera);
    restart(viewer);
}

// Orbit and dolly turn around a target at the scene's depth rather than the default one
// unit ahead. Placed on the first such move only, so that the pose of --camera-pos (and
// of the SPEC camera) is used unchanged, bit for bit, until the user moves.
void placePivot(Viewer& viewer) {
    if (viewer.pivotPlaced) return;
    viewer.pivotPlaced = true;
    viewer.camera = pivotAtScene(viewer.camera, viewer.bounds, std::max(viewer.bounds.radius, 1.0) * 1e-3);
}

// A new renderer for scene with the current settings, replacing the old one only when it
// could be made: a shader that does not compile keeps the last good pipeline.
bool rebuildRenderer(Viewer& viewer, const Scene& scene) {
    VK_CHECK(vkDeviceWaitIdle(viewer.context.device));
    Renderer fresh;
    try {
        createRenderer(fresh, viewer.context, scene, viewer.renderer.settings);
    } catch (const std::exception& error) {
        destroyRenderer(fresh, viewer.context);
        std::fprintf(stderr, "%s\nKeeping the last good kernel and scene.\n", error.what());
        return false;
    }
    destroyRenderer(viewer.renderer, viewer.context);
    viewer.renderer = fresh;
    viewer.bounds = sceneBounds(scene);
    restart(viewer);
    return true;
}

// Loads the scene file again; a parse error keeps the last good scene on screen.
void reloadScene(Viewer& viewer) {
    Scene scene;
    try {
        scene = loadScene(viewer.options->scenePath);
    } catch (const SceneError& error) {
        std::fprintf(stderr, "%s\nKeeping the last good scene.\n", error.what());
        return;
    }
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    if (rebuildRenderer(viewer, scene)) {
        viewer.scene = std::move(scene);
        std::fprintf(stderr, "Reloaded %s\n", viewer.options->scenePath.string().c_str());
    }
}

void reloadShaders(Viewer& viewer) {
    if (rebuildRenderer(viewer, viewer.scene))
        std::fprintf(stderr, "Reloaded the shaders%s%s\n", viewer.options->shaderDirectory.empty() ? "" : " from ",
                     viewer.options->shaderDirectory.string().c_str());
}

void pollWatchedFiles(Viewer& viewer) {
    const Clock::time_point now = Clock::now();
    if (std::chrono::duration<double>(now - viewer.lastWatch).count() < kWatchInterval) return;
    viewer.lastWatch = now;
    if (pathChanged(viewer.sceneWatch)) reloadScene(viewer);
    else if (!viewer.shaderWatch.path.empty() && pathChanged(viewer.shaderWatch)) reloadShaders(viewer);
}

void toggleVsync(Viewer& viewer) {
    viewer.vsync = !viewer.vsync;
    viewer.swapchainStale = true; // the loop recreates it with the new present mode
}

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    Viewer& viewer = viewerOf(window);
    switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    case GLFW_KEY_R:
        reloadScene(viewer); // also recompiles the shaders: the renderer is built anew
        break;
    case GLFW_KEY_P:
        viewer.screenshotPending = true;
        if (refining(viewer))
            std::fprintf(stderr, "Screenshot: written once all %u samples per pixel are in (%u so far)\n",
                         viewer.sampleTarget, viewer.samplesDone);
        break;
    case GLFW_KEY_V: toggleVsync(viewer); break;
    case GLFW_KEY_C:
    case GLFW_KEY_HOME:
        viewer.pivotPlaced = false;
        setCamera(viewer, CameraPose{});
        break;
    default: break;
    }
}

void onMouseButton(GLFWwindow* window, int button, int action, int) {
    Viewer& viewer = viewerOf(window);
    glfwGetCursorPos(window, &viewer.cursorX, &viewer.cursorY);
    if (button == GLFW_MOUSE_BUTTON_LEFT) viewer.leftDrag = action == GLFW_PRESS;
    if (button == GLFW_MOUSE_BUTTON_RIGHT) viewer.rightDrag = action == GLFW_PRESS;
}

void onCursor(GLFWwindow* window, double x, double y) {
    Viewer& viewer = viewerOf(window);
    const double dx = x - viewer.cursorX, dy = y - viewer.cursorY;
    viewer.cursorX = x;
    viewer.cursorY = y;
    if (viewer.leftDrag) {
        placePivot(viewer);
        setCamera(viewer, orbitCamera(viewer.camera, -dx * kOrbitPerPixel, dy * kOrbitPerPixel));
    } else if (viewer.rightDrag) {
        setCamera(viewer, lookCamera(viewer.camera, -dx * kLookPerPixel, -dy * kLookPerPixel));
    }
}

void onScroll(GLFWwindow* window, double, double steps) {
    Viewer& viewer = viewerOf(window);
    placePivot(viewer);
    setCamera(viewer, dollyCamera(viewer.camera, steps));
}

// W/A/S/D, Space and Left Shift held down: fly at a speed that crosses the scene in
// about four seconds. Returns whether one is held (the loop then keeps polling).
bool applyFlyKeys(Viewer& viewer) {
    const Clock::time_point now = Clock::now();
    const double seconds = std::min(std::chrono::duration<double>(now - viewer.lastMove).count(), 0.1);
    viewer.lastMove = now;
    auto held = [&](int key) { return glfwGetKey(viewer.window, key) == GLFW_PRESS ? 1.0 : 0.0; };
    const glm::dvec3 direction(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_SPACE) - held(GLFW_KEY_LEFT_SHIFT),
                               held(GLFW_KEY_W) - held(GLFW_KEY_S));
    if (direction == glm::dvec3(0.0)) return false;
    const double speed = std::max(viewer.bounds.radius, 1.0) * 0.5;
    setCamera(viewer, flyCamera(viewer.camera, direction * (speed * seconds)));
    return true;
}

void onFramebufferSize(GLFWwindow* window, int, int) { viewerOf(window).resized = true; }

// The window system lost the window's contents (it was exposed): show the image again.
void onRefresh(GLFWwindow* window) { viewerOf(window).presentNeeded = true; }

void open(Viewer& viewer, const Options& options, const Scene& scene) {
    viewer.options = &options;
    viewer.scene = scene;
    viewer.bounds = sceneBounds(scene);
    viewer.camera = options.camera;
    viewer.sceneName = options.scenePath.filename().string();
    viewer.continuous = options.redrawContinuously;
    viewer.benchFrames = options.benchWindowFrames;
    // The bench times the view at one sample per frame, without waiting for the display.
    viewer.sampleTarget = options.samplesGiven ? options.samplesPerPixel : kSampleCap;
    if (viewer.benchFrames > 0) {
        viewer.sampleTarget = std::max(viewer.sampleTarget, viewer.benchFrames + 1);
        viewer.vsync = false;
    }
    viewer.sceneWatch = watchPath(options.scenePath);
    if (!options.shaderDirectory.empty()) viewer.shaderWatch = watchPath(options.shaderDirectory);

    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan presents; no OpenGL context
    glfwWindowHintString(GLFW_X11_CLASS_NAME, "Raytracer");
    glfwWindowHintString(GLFW_X11_INSTANCE_NAME, "raytracer");
    std::string title = viewer.sceneName + " - rendering...";
    viewer.window = glfwCreateWindow(int(options.width), int(options.height), title.c_str(), nullptr, nullptr);
    if (!viewer.window) throw std::runtime_error("could not create a window (see the GLFW error above)");
    glfwSetWindowUserPointer(viewer.window, &viewer);
    glfwSetKeyCallback(viewer.window, onKey);
    glfwSetMouseButtonCallback(viewer.window, onMouseButton);
    glfwSetCursorPosCallback(viewer.window, onCursor);
    glfwSetScrollCallback(viewer.window, onScroll);
    glfwSetFramebufferSizeCallback(viewer.window, onFramebufferSize);
    glfwSetWindowRefreshCallback(viewer.window, onRefresh);

    if (!glfwVulkanSupported()) throw std::runtime_error("GLFW found no Vulkan loader for the window");
    std::uint32_t extensionCount = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
    if (!extensions) throw std::runtime_error("Vulkan cannot present to this window system");
    createInstance(viewer.context, {extensions, extensions + extensionCount}, options.validate);
    VK_CHECK(glfwCreateWindowSurface(viewer.context.instance, viewer.window, nullptr, &viewer.surface));
    createDevice(viewer.context, options.device, viewer.surface,
                 options.kernel.precision == Precision::Fp64);

    // The output starts at the requested size; the first swapchain adjusts it to the
    // framebuffer's size, should the window system have chosen another.
    RenderSettings settings{options.width, options.height, viewer.sampleTarget, options.depth,
                            glm::vec3(options.background), options.fovDegrees,
                            options.acceleration};
    settings.cacheDirectory = userCacheDirectory(options.useCache);
    settings.camera = viewer.camera;
    settings.shaderDirectory = options.shaderDirectory;
    settings.kernel = options.kernel;
    settings.generalKernel = options.generalKernel;
    settings.progressive = true;
    createRenderer(viewer.renderer, viewer.context, scene, settings);

    VkDevice device = viewer.context.device;
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT; // the first wait on each frame returns at once
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = viewer.context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    for (Frame& frame : viewer.frames) {
        VK_CHECK(vkAllocateCommandBuffers(device, &allocateInfo, &frame.commands));
        VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &frame.imageAvailable));
        VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &frame.done));
    }
}

// Makes a swapchain for the current framebuffer size and the output image to match.
// Returns false when the window is minimised (0x0): nothing to draw into.
bool refreshSwapchain(Viewer& viewer) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(viewer.window, &width, &height);
    if (width <= 0 || height <= 0) return false;
    VkExtent2D size{std::uint32_t(width), std::uint32_t(height)};
    const VkPresentModeKHR oldMode = viewer.swapchain.presentMode;
    const bool existed = viewer.swapchain.swapchain != VK_NULL_HANDLE;
    bool created = existed ? recreateSwapchain(viewer.swapchain, viewer.context, viewer.surface, size, viewer.vsync)
                           : createSwapchain(viewer.swapchain, viewer.context, viewer.surface, size, viewer.vsync);
    if (!created) return false;
    if (existed && viewer.swapchain.presentMode != oldMode)
        std::fprintf(stderr, "Vsync %s (present mode %s)\n", viewer.vsync ? "on" : "off",
                     presentModeName(viewer.swapchain.presentMode));
    viewer.swapchainStale = false;
    viewer.presentNeeded = true;
    // The blit copies 1:1, so the output image always has the swapchain's size.
    const VkExtent2D extent = viewer.swapchain.extent;
    if (extent.width != viewer.renderer.outputImage.width || extent.height != viewer.renderer.outputImage.height) {
        resizeOutput(viewer.renderer, viewer.context, extent.width, extent.height);
        restart(viewer);
    }
    return true;
}

// Traces the next samples if any are owed, then blits the output image into the
// swapchain image.
void record(const Viewer& viewer, VkCommandBuffer commands, VkImage target, SampleRange samples) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    // Without a trace the output image still holds the last one, in TRANSFER_SRC_OPTIMAL,
    // made visible to transfer reads by the barrier that ended that trace.
    if (samples.count > 0) recordTrace(viewer.renderer, commands, samples);

    // The swapchain image's old contents are discarded (UNDEFINED). The submit waits on
    // image-available at the TRANSFER stage, so this barrier, which starts at that stage,
    // orders the layout change and the blit's writes after the presentation engine let go.
    transitionImage(commands, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT);
    // Same size, nearest filter: every pixel is copied unchanged. RGBA8 to BGRA8 UNORM
    // swaps channels only; the 8-bit values stay exact.
    const Image& output = viewer.renderer.outputImage;
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {int32_t(output.width), int32_t(output.height), 1};
    region.dstSubresource = region.srcSubresource;
    region.dstOffsets[1] = region.srcOffsets[1];
    vkCmdBlitImage(commands, output.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    // Hand the image to presentation once the blit has written it. The present waits on
    // the render-finished semaphore, which makes the writes visible, so no access follows.
    transitionImage(commands, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    VK_CHECK(vkEndCommandBuffer(commands));
}

// "NAME - WxH - k/N spp - T ms - DEVICE": the tests wait for "k/N spp" with k == N.
void showTitle(const Viewer& viewer) {
    char title[512];
    std::snprintf(title, sizeof(title), "%s - %ux%u - %u/%u spp - %.1f ms - %s", viewer.sceneName.c_str(),
                  viewer.renderer.outputImage.width, viewer.renderer.outputImage.height, viewer.samplesDone,
                  viewer.sampleTarget, viewer.lastFrameMs, viewer.context.properties.deviceName);
    glfwSetWindowTitle(viewer.window, title);
}

// More samples per frame while frames are quick, fewer when slow. The bench keeps one.
void adaptSamplesPerFrame(Viewer& viewer, double milliseconds) {
    if (viewer.benchFrames > 0) return;
    if (milliseconds < kFastFrameMs) viewer.samplesPerFrame = std::min(viewer.samplesPerFrame * 2, kMaxSamplesPerFrame);
    else if (milliseconds > kSlowFrameMs) viewer.samplesPerFrame = std::max(viewer.samplesPerFrame / 2, 1u);
}

// Acquire, record, submit, present. A stale swapchain is only noted here; the loop
// recreates it and presents again.
void drawFrame(Viewer& viewer) {
    VkDevice device = viewer.context.device;
    Frame& frame = viewer.frames[viewer.frameIndex];
    VK_CHECK(vkWaitForFences(device, 1, &frame.done, VK_TRUE, UINT64_MAX));
    std::uint32_t imageIndex = 0;
    VkResult acquired = vkAcquireNextImageKHR(device, viewer.swapchain.swapchain, UINT64_MAX,
                                              frame.imageAvailable, VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        viewer.swapchainStale = true; // nothing was acquired, the semaphore stays unsignalled
        return;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) VK_CHECK(acquired); // suboptimal still acquired an image: use it
    VK_CHECK(vkResetFences(device, 1, &frame.done));
    SampleRange samples;
    if (refining(viewer))
        samples = {viewer.samplesDone, std::min(viewer.samplesPerFrame, viewer.sampleTarget - viewer.samplesDone)};
    record(viewer, frame.commands, viewer.swapchain.images[imageIndex], samples);

    VkSemaphore renderFinished = viewer.swapchain.renderFinished[imageIndex];
    VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT; // the first use of the image is the blit
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &frame.imageAvailable;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderFinished;
    const Clock::time_point submitted = Clock::now();
    VK_CHECK(vkQueueSubmit(viewer.context.queue, 1, &submit, frame.done));

    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderFinished;
    present.swapchainCount = 1;
    present.pSwapchains = &viewer.swapchain.swapchain;
    present.pImageIndices = &imageIndex;
    VkResult presented = vkQueuePresentKHR(viewer.context.queue, &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR || acquired == VK_SUBOPTIMAL_KHR)
        viewer.swapchainStale = true; // presentNeeded stays set: show it again on the new swapchain
    else {
        VK_CHECK(presented);
        viewer.presentNeeded = false;
    }
    viewer.frameIndex = (viewer.frameIndex + 1) % kFramesInFlight;

    // A traced frame is waited for: it times the frame exactly (submit to fence), which
    // sizes the next one, and input is then never more than one frame behind.
    if (samples.count > 0) {
        VK_CHECK(vkWaitForFences(device, 1, &frame.done, VK_TRUE, UINT64_MAX));
        viewer.lastFrameMs = std::chrono::duration<double, std::milli>(Clock::now() - submitted).count();
        viewer.samplesDone += samples.count;
        adaptSamplesPerFrame(viewer, viewer.lastFrameMs);
        // One line per finished image (the tests wait for it), none while soaking.
        if (!refining(viewer) && !viewer.continuous && viewer.benchFrames == 0)
            std::fprintf(stderr, "Refined: %u samples per pixel at %ux%u in %.2f s\n", viewer.sampleTarget,
                         viewer.renderer.outputImage.width, viewer.renderer.outputImage.height,
                         std::chrono::duration<double>(Clock::now() - viewer.refineStart).count());
        showTitle(viewer);
        viewer.presentNeeded = viewer.presentNeeded || refining(viewer);
    }
    if (viewer.benchFrames > 0 && samples.count > 0) {
        if (viewer.benchCounted++ == 0) viewer.benchStart = Clock::now(); // the first frame warms up
        else viewer.benchSamples += samples.count;
    }
}

void writeScreenshot(Viewer& viewer) {
    viewer.screenshotPending = false;
    const Options& options = *viewer.options;
    const std::filesystem::path path =
        nextScreenshotPath(std::filesystem::current_path(), options.scenePath.stem().string());
    const Image8 image = readOutputImage(viewer.context, viewer.renderer);
    writePng(path, image);
    const std::string command =
        headlessCommand(options, viewer.camera, image.width, image.height, viewer.sampleTarget);
    std::fprintf(stderr,
                 "Screenshot: wrote %s (%dx%d, %u samples per pixel); the same image headless: %s\n",
                 path.string().c_str(), image.width, image.height, viewer.sampleTarget, command.c_str());
}

// --bench-window: once N frames after the first are done, prints one JSON line and ends.
void finishBenchIfDone(Viewer& viewer) {
    if (viewer.benchFrames == 0 || viewer.benchCounted <= viewer.benchFrames) return;
    const double seconds = std::chrono::duration<double>(Clock::now() - viewer.benchStart).count();
    const Image& output = viewer.renderer.outputImage;
    std::printf("{\"scene\": \"%s\", \"device\": \"%s\", \"width\": %u, \"height\": %u, \"frames\": %u, "
                "\"seconds\": %.3f, \"fps\": %.2f, \"samples_per_frame\": 1, \"megasamples_per_second\": %.3f}\n",
                viewer.sceneName.c_str(), viewer.context.properties.deviceName, output.width, output.height,
                viewer.benchFrames, seconds, viewer.benchFrames / seconds,
                double(viewer.benchSamples) * output.width * output.height / seconds * 1e-6);
    std::fflush(stdout);
    glfwSetWindowShouldClose(viewer.window, GLFW_TRUE);
}

void runLoop(Viewer& viewer) {
    while (!glfwWindowShouldClose(viewer.window)) {
        if (viewer.continuous) {
            restart(viewer);
            viewer.presentNeeded = true;
        }
        // Sleep until something happens, or the next look at the files, unless a frame
        // is still owed or the user is flying.
        const bool busy = viewer.presentNeeded || viewer.swapchainStale || viewer.resized || refining(viewer) ||
                          viewer.leftDrag || viewer.rightDrag;
        if (busy) glfwPollEvents();
        else glfwWaitEventsTimeout(kWatchInterval);
        if (glfwWindowShouldClose(viewer.window)) break;
        pollWatchedFiles(viewer);
        if (applyFlyKeys(viewer)) viewer.presentNeeded = true;
        if (viewer.resized) {
            viewer.resized = false;
            viewer.swapchainStale = true;
        }
        if (viewer.swapchainStale && !refreshSwapchain(viewer)) {
            glfwWaitEventsTimeout(kWatchInterval); // minimised: draw nothing until the window changes
            continue;
        }
        if (viewer.presentNeeded || refining(viewer)) drawFrame(viewer);
        if (viewer.screenshotPending && !refining(viewer) && !viewer.continuous) writeScreenshot(viewer);
        finishBenchIfDone(viewer);
    }
}

// Everything in reverse order of creation, once the device is idle. Safe on a
// partly opened viewer. The surface goes before the device here only because
// destroyContext removes device and instance together; its swapchain is gone by then.
void close(Viewer& viewer) {
    VkDevice device = viewer.context.device;
    if (device) {
        vkDeviceWaitIdle(device);
        for (Frame& frame : viewer.frames) {
            if (frame.done) vkDestroyFence(device, frame.done, nullptr);
            if (frame.imageAvailable) vkDestroySemaphore(device, frame.imageAvailable, nullptr);
            if (frame.commands) vkFreeCommandBuffers(device, viewer.context.commandPool, 1, &frame.commands);
            frame = Frame{};
        }
    }
    destroySwapchain(viewer.swapchain, viewer.context);
    destroyRenderer(viewer.renderer, viewer.context);
    if (viewer.surface) vkDestroySurfaceKHR(viewer.context.instance, viewer.surface, nullptr);
    viewer.surface = VK_NULL_HANDLE;
    destroyContext(viewer.context);
    if (viewer.window) glfwDestroyWindow(viewer.window);
    viewer.window = nullptr;
}

} // namespace

std::string windowUnavailableReason() { return glfwInitError.empty() ? "GLFW could not start" : glfwInitError; }

bool runWindow(const Options& options, const Scene& scene) {
    glfwSetErrorCallback(onGlfwError);
    glfwInitError.clear();
    if (!glfwInit()) return false; // no display: the caller renders headless
    glfwReady = true;
    Viewer viewer;
    try {
        open(viewer, options, scene);
        std::fputs(kHelpLine, stderr);
        runLoop(viewer);
    } catch (...) {
        close(viewer);
        glfwReady = false;
        glfwTerminate();
        throw;
    }
    close(viewer);
    glfwReady = false;
    glfwTerminate();
    return true;
}
