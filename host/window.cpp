// The interactive window. The scene is static, so a frame is traced only when the
// framebuffer size changes; an exposed window is presented again from the last trace,
// and an idle window sleeps in glfwWaitEvents.
#include "window.h"

#include "pipeline_cache.h"
#include "renderer.h"
#include "swapchain.h"
#include "vk_check.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

// Enough for a blit-only present to be recorded while the previous one still runs.
constexpr std::uint32_t kFramesInFlight = 2;

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
    GLFWwindow* window = nullptr;
    Context context;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    Renderer renderer;
    Swapchain swapchain;
    Frame frames[kFramesInFlight];
    std::uint32_t frameIndex = 0;
    std::string sceneName;       // the title's first part
    bool resized = false;        // the framebuffer changed size: new swapchain, maybe a new trace
    bool swapchainStale = true;  // no usable swapchain yet, or OUT_OF_DATE/SUBOPTIMAL was reported
    bool traceNeeded = true;     // the output image does not hold the current frame
    bool presentNeeded = true;   // the window does not show the output image
    bool continuous = false;     // --redraw-continuously: trace every frame (soak test)
};

Viewer& viewerOf(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_PRESS && (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q))
        glfwSetWindowShouldClose(window, GLFW_TRUE);
}

void onFramebufferSize(GLFWwindow* window, int, int) { viewerOf(window).resized = true; }

// The window system lost the window's contents (it was exposed): show the image again.
void onRefresh(GLFWwindow* window) { viewerOf(window).presentNeeded = true; }

void open(Viewer& viewer, const Options& options, const Scene& scene) {
    viewer.sceneName = options.scenePath.filename().string();
    viewer.continuous = options.redrawContinuously;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan presents; no OpenGL context
    glfwWindowHintString(GLFW_X11_CLASS_NAME, "Raytracer");
    glfwWindowHintString(GLFW_X11_INSTANCE_NAME, "raytracer");
    std::string title = viewer.sceneName + " - rendering...";
    viewer.window = glfwCreateWindow(int(options.width), int(options.height), title.c_str(), nullptr, nullptr);
    if (!viewer.window) throw std::runtime_error("could not create a window (see the GLFW error above)");
    glfwSetWindowUserPointer(viewer.window, &viewer);
    glfwSetKeyCallback(viewer.window, onKey);
    glfwSetFramebufferSizeCallback(viewer.window, onFramebufferSize);
    glfwSetWindowRefreshCallback(viewer.window, onRefresh);

    if (!glfwVulkanSupported()) throw std::runtime_error("GLFW found no Vulkan loader for the window");
    std::uint32_t extensionCount = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
    if (!extensions) throw std::runtime_error("Vulkan cannot present to this window system");
    createInstance(viewer.context, {extensions, extensions + extensionCount}, options.validate);
    VK_CHECK(glfwCreateWindowSurface(viewer.context.instance, viewer.window, nullptr, &viewer.surface));
    createDevice(viewer.context, options.device, viewer.surface);

    // The output starts at the requested size; the first swapchain adjusts it to the
    // framebuffer's size, should the window system have chosen another.
    RenderSettings settings{options.width, options.height, options.samplesPerPixel, options.depth,
                            glm::vec3(options.background), options.fovDegrees,
                            options.acceleration};
    settings.cacheDirectory = userCacheDirectory(options.useCache);
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
    bool created = viewer.swapchain.swapchain
                       ? recreateSwapchain(viewer.swapchain, viewer.context, viewer.surface, size)
                       : createSwapchain(viewer.swapchain, viewer.context, viewer.surface, size);
    if (!created) return false;
    viewer.swapchainStale = false;
    viewer.presentNeeded = true;
    // The blit copies 1:1, so the output image always has the swapchain's size.
    const VkExtent2D extent = viewer.swapchain.extent;
    if (extent.width != viewer.renderer.outputImage.width || extent.height != viewer.renderer.outputImage.height) {
        resizeOutput(viewer.renderer, viewer.context, extent.width, extent.height);
        viewer.traceNeeded = true;
    }
    return true;
}

// Traces if needed, then blits the output image into the swapchain image.
void record(const Viewer& viewer, VkCommandBuffer commands, VkImage target) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    // Without a trace the output image still holds the last one, in TRANSFER_SRC_OPTIMAL,
    // made visible to transfer reads by the barrier that ended that trace.
    if (viewer.traceNeeded) recordTrace(viewer.renderer, commands);

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

void showFrameTime(const Viewer& viewer, double milliseconds) {
    char title[256];
    std::snprintf(title, sizeof(title), "%s - %ux%u - %.1f ms", viewer.sceneName.c_str(),
                  viewer.renderer.outputImage.width, viewer.renderer.outputImage.height, milliseconds);
    glfwSetWindowTitle(viewer.window, title);
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
    const bool tracing = viewer.traceNeeded;
    record(viewer, frame.commands, viewer.swapchain.images[imageIndex]);

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
    const auto submitted = std::chrono::steady_clock::now();
    VK_CHECK(vkQueueSubmit(viewer.context.queue, 1, &submit, frame.done));
    viewer.traceNeeded = false;

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

    // Frames come only on change, so waiting here costs nothing and times the frame
    // exactly: from submit to fence.
    if (tracing) {
        VK_CHECK(vkWaitForFences(device, 1, &frame.done, VK_TRUE, UINT64_MAX));
        showFrameTime(viewer, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                         submitted).count());
    }
}

void runLoop(Viewer& viewer) {
    while (!glfwWindowShouldClose(viewer.window)) {
        if (viewer.continuous) viewer.traceNeeded = viewer.presentNeeded = true;
        // Sleep until something happens, unless a frame is still owed.
        if (viewer.presentNeeded || viewer.swapchainStale || viewer.resized)
            glfwPollEvents();
        else
            glfwWaitEvents();
        if (glfwWindowShouldClose(viewer.window)) break;
        if (viewer.resized) {
            viewer.resized = false;
            viewer.swapchainStale = true;
        }
        if (viewer.swapchainStale && !refreshSwapchain(viewer)) {
            glfwWaitEvents(); // minimised: draw nothing until the window changes
            continue;
        }
        if (viewer.presentNeeded) drawFrame(viewer);
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
        std::fprintf(stderr, "Window: Esc or Q quits; resize to re-render.\n");
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
