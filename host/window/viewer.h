// The interactive window's state, shared by the files that make it up: window.cpp (open,
// frame loop, close), input.cpp (keys and mouse), present.cpp (trace, blit,
// present), reload.cpp (hot reload), capture.cpp (screenshot, bench) and overlay.cpp
// (the ImGui panel).
// Internal to the window: nothing outside those files includes it.
#pragma once

#include <cstdio>

#include "base/file_watch.h"
#include "cli/options.h"
#include "compare/comparison.h"
#include "gpu/context.h"
#include "model/model_scene.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "window/swapchain.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

using Clock = std::chrono::steady_clock;

// Enough for a blit-only present to be recorded while the previous one still runs.
constexpr std::uint32_t kFramesInFlight = 2;

struct Frame {
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkSemaphore imageAvailable = VK_NULL_HANDLE; // signalled by acquire, waited on by the submit
    VkFence done = VK_NULL_HANDLE;               // the submit finished; created signalled
};

// The overlay's Vulkan objects (window/overlay.h); ImGui holds the rest.
struct Overlay {
    bool created = false;
    bool shown = false;                               // H toggles; --overlay opens it shown
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE; // the font texture's descriptor set
    VkRenderPass renderPass = VK_NULL_HANDLE; // loads the blitted image, draws, hands it to present
    VkFormat format = VK_FORMAT_UNDEFINED;    // the swapchain format renderPass was made for
    std::vector<VkImageView> views;           // one per swapchain image
    std::vector<VkFramebuffer> framebuffers;
};

// --compare FILE: what the window shows (keys 1, 2, 3, F), and the pictures other than the
// render (window/compare_view.h).
enum class ComparedPicture { Render, Image, Difference };
struct CompareView {
    const Comparison* comparison = nullptr; // none: the window compares nothing
    ComparedPicture shown = ComparedPicture::Render;
    Image8 image, difference;
    Image picture; // the image or the difference, as shown now; TRANSFER_SRC_OPTIMAL
};

struct Viewer {
    // The command line's options as the window uses them now: the overlay's switches change
    // this copy, so that P's headless command names what is shown.
    Options options;
    GLFWwindow* window = nullptr;
    Context context;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    Renderer renderer;
    Swapchain swapchain;
    Frame frames[kFramesInFlight];
    Overlay overlay;
    CompareView compare;
    std::uint32_t frameIndex = 0;
    std::string sceneName; // the title's first part
    Scene scene;           // the last scene that loaded, for shader reloads

    // Progressive refinement: samples 0..samplesDone-1 of sampleTarget are in the sum, or,
    // with 1 of more, the one-sample image (the pixel centre) of the view's first frame.
    std::uint32_t sampleTarget = 1;
    std::uint32_t samplesDone = 0;
    std::uint32_t samplesPerFrame = 1;
    double lastFrameMs = 0.0;
    std::uint32_t lastFrameSamples = 0; // samples per pixel the last traced frame added
    // The driver cut invocations short even at one sample per dispatch, and the warning
    // has been printed (once per window).
    bool cutShortReported = false;
    Clock::time_point refineStart = Clock::now();

    CameraPose camera;
    bool pivotPlaced = false; // the orbit target sits at the scene's depth (see pivotAtScene)
    SceneBounds bounds;
    bool leftDrag = false, rightDrag = false;
    double cursorX = 0.0, cursorY = 0.0;
    Clock::time_point lastMove = Clock::now();

    FileWatch sceneWatch, shaderWatch;
    Clock::time_point lastWatch = Clock::now();

    bool resized = false;       // the framebuffer changed size: new swapchain, maybe a new trace
    bool swapchainStale = true; // no usable swapchain yet, or OUT_OF_DATE/SUBOPTIMAL was reported
    bool presentNeeded = true;  // the window does not show the output image
    bool vsync = true;
    bool snapshotNow = false; // P: write what is shown, after this frame
    // --snapshots: the sample counts at which the first view's refinement writes a screenshot,
    // and the index of the next one (the series ends when the view changes).
    std::vector<std::uint32_t> snapshotCounts;
    std::size_t nextSnapshot = 0;
    bool screenshotPending = false;     // Shift+P: write it once refinement is done
    bool screenshotViewChanged = false; // the camera moved since Shift+P (said once)
    // I: print the pixel story of the pixel at (storyX, storyY), window units, after the
    // frame: under the mouse when I was pressed, or where the left button was clicked with
    // I held (storyClicked).
    bool storyPending = false;
    bool storyClicked = false;
    double storyX = 0.0, storyY = 0.0;
    bool rigStale = false;   // the camera moved and the scene's lights are an OBJ model's rig
    bool continuous = false; // --redraw-continuously: restart the sum every frame (soak test)

    // --bench-window N: frames timed after the first.
    std::uint32_t benchFrames = 0, benchCounted = 0;
    std::uint64_t benchSamples = 0;
    Clock::time_point benchStart;
};

inline bool refining(const Viewer& viewer) {
    return viewer.samplesDone < viewer.sampleTarget;
}

// The sum starts again from its first sample, for the same image.
inline void restartSum(Viewer& viewer) {
    if (viewer.samplesDone != 0) viewer.refineStart = Clock::now();
    viewer.samplesDone = 0;
    viewer.samplesPerFrame = 1; // the first frame after a change comes quickly
}

// Something the image depends on changed: the sum starts again. A --snapshots series under
// way ends: it belongs to the view the window opened with.
inline void restartRefinement(Viewer& viewer) {
    if (viewer.samplesDone != 0 && viewer.nextSnapshot < viewer.snapshotCounts.size()) {
        std::fprintf(stderr,
                     "Snapshots: the view changed at %u samples per pixel; no more snapshots are "
                     "written\n",
                     viewer.samplesDone);
        viewer.nextSnapshot = viewer.snapshotCounts.size();
    }
    restartSum(viewer);
}

// A Shift+P request waiting when the view changes is for the new view, and says so (once
// per request), rather than silently becoming another image.
inline void setCamera(Viewer& viewer, const CameraPose& camera) {
    if (viewer.screenshotPending && !viewer.screenshotViewChanged && camera != viewer.camera) {
        viewer.screenshotViewChanged = true;
        std::fprintf(stderr,
                     "Screenshot: the view moved before its %u samples per pixel were in; "
                     "the request now waits for the new view\n",
                     viewer.sampleTarget);
    }
    viewer.camera = camera;
    setCamera(viewer.renderer, camera);
    // An OBJ model's rig follows the camera; the lights are rewritten once before the next
    // trace (placeRigForCamera), not at every mouse event.
    if (viewer.scene.lightRig) viewer.rigStale = true;
    restartRefinement(viewer);
}

// The rig placed again for the current camera, when it moved: the few lights are rewritten
// in the scene buffer; the kernel and the rest of the scene stay.
inline void placeRigForCamera(Viewer& viewer) {
    if (!viewer.rigStale) return;
    viewer.rigStale = false;
    placeLightRig(viewer.scene, viewer.camera);
    setLights(viewer.renderer, viewer.context, viewer.scene.lights);
}
