// What the window writes out: the P key's screenshot (once refinement is done, so it is
// the headless image at the same settings) and the one JSON line of --bench-window.
#include "window/capture.h"

#include "cli/command_line.h"
#include "window/screenshot.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

void writeScreenshot(Viewer& viewer) {
    viewer.screenshotPending = false;
    const Options& options = *viewer.options;
    const std::filesystem::path path =
        nextScreenshotPath(std::filesystem::current_path(), options.scenePath.stem().string());
    const Image8 image = readOutputImage(viewer.context, viewer.renderer);
    writePng(path, image);
    const std::string command =
        headlessCommand(options, viewer.camera, image.width, image.height, viewer.sampleTarget);
    std::fprintf(
        stderr, "Screenshot: wrote %s (%dx%d, %u samples per pixel); the same image headless: %s\n",
        path.string().c_str(), image.width, image.height, viewer.sampleTarget, command.c_str());
}

void countBenchFrame(Viewer& viewer, std::uint32_t samples) {
    if (viewer.benchFrames == 0) return;
    if (viewer.benchCounted++ == 0)
        viewer.benchStart = Clock::now(); // the first frame warms up
    else
        viewer.benchSamples += samples;
}

void finishBenchIfDone(Viewer& viewer) {
    if (viewer.benchFrames == 0 || viewer.benchCounted <= viewer.benchFrames) return;
    const double seconds = std::chrono::duration<double>(Clock::now() - viewer.benchStart).count();
    const Image& output = viewer.renderer.outputImage;
    std::printf(
        "{\"scene\": \"%s\", \"device\": \"%s\", \"width\": %u, \"height\": %u, \"frames\": %u, "
        "\"seconds\": %.3f, \"fps\": %.2f, \"samples_per_frame\": 1, \"megasamples_per_second\": "
        "%.3f}\n",
        viewer.sceneName.c_str(), viewer.context.properties.deviceName, output.width, output.height,
        viewer.benchFrames, seconds, viewer.benchFrames / seconds,
        double(viewer.benchSamples) * output.width * output.height / seconds * 1e-6);
    std::fflush(stdout);
    glfwSetWindowShouldClose(viewer.window, GLFW_TRUE);
}
