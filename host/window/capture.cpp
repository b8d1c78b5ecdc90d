// What the window writes out: the P key's screenshot of what is shown, Shift+P's once
// refinement is done (the headless image at the same settings), and the one JSON line of
// --bench-window.
#include "window/capture.h"

#include "base/json.h"
#include "cli/command_line.h"
#include "window/compare_view.h"
#include "window/screenshot.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

// The headless twin of an image of `samples` samples per pixel: exact when refinement is
// done, at one sample (the window's first frame is the one-sample image), or with the r2
// sampler, whose sample s does not depend on the sample count (the window adds samples
// 0..s-1 in the order a headless render does).
std::string headlessTwin(const Viewer& viewer, std::uint32_t width, std::uint32_t height,
                         std::uint32_t samples) {
    const Options& options = viewer.options;
    if (samples != viewer.sampleTarget && samples != 1 && options.kernel.sampler != Sampler::R2)
        return "; the " + choiceName(samplerNames(), options.kernel.sampler) +
               " sampler places its samples by their count, so only the finished image (" +
               std::to_string(viewer.sampleTarget) + " samples) has a headless twin";
    return "; the same image headless: " +
           headlessCommand(options, viewer.camera, int(width), int(height), samples);
}

} // namespace

void writeScreenshot(Viewer& viewer) {
    viewer.snapshotNow = false;
    viewer.screenshotPending = false;
    viewer.screenshotViewChanged = false;
    const Options& options = viewer.options;
    const std::uint32_t samples = viewer.samplesDone;
    const std::filesystem::path path = nextScreenshotPath(
        std::filesystem::current_path(), options.scenePath.stem().string(), samples);
    if (const Image8* shown = comparedBytes(viewer)) { // --compare: the image or the difference
        writePng(path, *shown);
        std::fprintf(stderr, "Screenshot: wrote %s (%dx%d, %s)\n", path.string().c_str(),
                     shown->width, shown->height,
                     viewer.compare.shown == ComparedPicture::Image ? "your image"
                                                                    : "the difference");
        return;
    }
    const Image8 image = readOutputImage(viewer.context, viewer.renderer);
    writePng(path, image);
    const std::string of = samples == viewer.sampleTarget
                               ? ""
                               : " of " + std::to_string(viewer.sampleTarget) + ", still refining";
    std::fprintf(stderr, "Screenshot: wrote %s (%dx%d, %u samples per pixel%s)%s\n",
                 path.string().c_str(), image.width, image.height, samples, of.c_str(),
                 headlessTwin(viewer, image.width, image.height, samples).c_str());
}

void dropPendingScreenshot(const Viewer& viewer) {
    if (!viewer.screenshotPending) return;
    const Image& output = viewer.renderer.outputImage;
    std::fprintf(stderr, "Screenshot: dropped, the window closed at %u of %u samples per pixel%s\n",
                 viewer.samplesDone, viewer.sampleTarget,
                 headlessTwin(viewer, output.width, output.height, viewer.sampleTarget).c_str());
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
    std::printf("{\"scene\": %s, \"device\": %s, \"width\": %u, \"height\": %u, \"frames\": %u, "
                "\"seconds\": %.3f, \"fps\": %.2f, \"samples_per_frame\": 1, "
                "\"megasamples_per_second\": %.3f}\n",
                jsonString(viewer.sceneName).c_str(),
                jsonString(viewer.context.properties.deviceName).c_str(), output.width,
                output.height, viewer.benchFrames, seconds, viewer.benchFrames / seconds,
                double(viewer.benchSamples) * output.width * output.height / seconds * 1e-6);
    std::fflush(stdout);
    glfwSetWindowShouldClose(viewer.window, GLFW_TRUE);
}
