// Hot reload: a new renderer for a saved scene file or shader folder (or the R key),
// swapped in only when it could be built, so that a typo keeps the last good image.
#include "window/reload.h"
#include "model/scene_file.h"

#include "cli/options.h"
#include "cli/render_settings.h"
#include "gpu/vk_check.h"
#include "scene/scene_loader.h"
#include "scene/scene_summary.h"

#include <cstdio>
#include <exception>
#include <utility>

namespace {

// A new renderer for scene with the current settings, replacing the old one only when it
// could be made: a shader that does not compile keeps the last good pipeline.
bool rebuildRenderer(Viewer& viewer, const Scene& scene, const RenderSettings& settings) {
    VK_CHECK(vkDeviceWaitIdle(viewer.context.device));
    Renderer fresh;
    try {
        createRenderer(fresh, viewer.context, scene, settings);
    } catch (const std::exception& error) { // createRenderer released what it made
        std::fprintf(stderr, "%s\nKeeping the last good kernel and scene.\n", error.what());
        return false;
    }
    destroyRenderer(viewer.renderer, viewer.context);
    viewer.renderer = fresh;
    viewer.bounds = subjectBounds(scene, viewer.camera, viewer.options.fovDegrees,
                                  double(viewer.options.width) / double(viewer.options.height));
    restartRefinement(viewer);
    return true;
}

void reloadShaders(Viewer& viewer) {
    if (rebuildRenderer(viewer, viewer.scene, viewer.renderer.settings))
        std::fprintf(stderr, "Reloaded the shaders%s%s\n",
                     viewer.options.shaderDirectory.empty() ? "" : " from ",
                     viewer.options.shaderDirectory.string().c_str());
}

} // namespace

void reloadScene(Viewer& viewer) {
    Scene scene;
    try {
        scene = loadScene(viewer.options.scenePath, objSceneSetup(viewer.options));
    } catch (const SceneError& error) {
        std::fprintf(stderr, "%s\nKeeping the last good scene.\n", error.what());
        return;
    }
    for (const std::string& line : loadMessages(scene, viewer.options.scenePath.string()))
        std::fprintf(stderr, "%s\n", line.c_str());
    placeLightRig(scene, viewer.camera); // a model's rig for where the window's camera is now
    if (rebuildRenderer(viewer, scene, viewer.renderer.settings)) {
        viewer.scene = std::move(scene);
        std::fprintf(stderr, "Reloaded %s\n", viewer.options.scenePath.string().c_str());
    }
}

void pollWatchedFiles(Viewer& viewer) {
    const Clock::time_point now = Clock::now();
    if (std::chrono::duration<double>(now - viewer.lastWatch).count() < kWatchInterval) return;
    viewer.lastWatch = now;
    if (pathChanged(viewer.sceneWatch))
        reloadScene(viewer);
    else if (!viewer.shaderWatch.path.empty() && pathChanged(viewer.shaderWatch))
        reloadShaders(viewer);
}

bool applyOptions(Viewer& viewer, const Options& options) {
    // The fields renderSettingsFrom takes from these options; the window's own (its size,
    // camera and running sum) stay as they are.
    RenderSettings settings = viewer.renderer.settings;
    const RenderSettings given = renderSettingsFrom(options);
    settings.depth = given.depth;
    settings.acceleration = given.acceleration;
    settings.kernel = given.kernel;
    // Without --spp the window refines to its own cap, as it did.
    const std::uint32_t target =
        options.samplesGiven ? options.samplesPerPixel : viewer.sampleTarget;
    settings.samplesPerPixel = target;
    if (!rebuildRenderer(viewer, viewer.scene, settings)) return false;
    viewer.options = options;
    viewer.sampleTarget = target;
    viewer.presentNeeded = true;
    return true;
}
