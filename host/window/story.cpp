#include "window/story.h"

#include "cli/window_keys.h"
#include "render/pixel_story.h"
#include "window/compare_view.h"

#include <cstdio>
#include <exception>

void printStoryUnderCursor(Viewer& viewer) {
    viewer.storyPending = false;
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(viewer.window, &windowWidth, &windowHeight);
    const Image& output = viewer.renderer.outputImage;
    const std::optional<glm::uvec2> pixel = pixelUnderCursor(
        viewer.storyX, viewer.storyY, windowWidth, windowHeight, output.width, output.height);
    // The click's line says so: a test tells a click's story from the I key's by it.
    const char* which = viewer.storyClicked ? "clicked pixel" : "pixel";
    if (!pixel) {
        std::fprintf(stderr, "Pixel story: the mouse is not over the image\n");
        return;
    }
    if (viewer.compare.comparison) { // --compare: the pixel's diagnosis instead of its story
        printPixelDiagnosis(viewer, *pixel);
        std::fprintf(stderr, "Diagnosis: %s %u,%u printed on stdout\n", which, pixel->x, pixel->y);
        return;
    }
    const RenderSettings& settings = viewer.renderer.settings;
    try {
        // Called after the loop's frame, so the output image holds a trace and is in
        // TRANSFER_SRC_OPTIMAL (the layout each trace leaves it in).
        const gpu::GpuPixelStory story =
            tracePixelStory(viewer.renderer, viewer.context, pixel->x, pixel->y,
                            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        const StoryHeader header{
            viewer.options.scenePath.string(), pixel->x,      pixel->y, output.width, output.height,
            settings.samplesPerPixel,          settings.depth};
        std::fputs(pixelStoryJson(story, viewer.renderer.sources, header).c_str(), stdout);
        std::fflush(stdout);
        std::fprintf(stderr, "Pixel story: %s %u,%u printed on stdout\n", which, pixel->x,
                     pixel->y);
    } catch (const std::exception& error) { // a --shader-dir kernel that does not compile
        std::fprintf(stderr, "Pixel story: %s\n", error.what());
    }
}
