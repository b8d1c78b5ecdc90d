#include "batch.h"

#include "base/notes.h"
#include "base/output_format.h"
#include "base/scope_guard.h"
#include "cli/output_pattern.h"
#include "cli/render_settings.h"
#include "model/scene_file.h"
#include "render/device_capacity.h"
#include "render/headless.h"
#include "render/interrupt.h"
#include "render/kernel_cache.h"
#include "scene/camera_path.h"
#include "scene/scene_loader.h"
#include "scene/scene_summary.h"

#include <iostream>

namespace {

// What one frame of a scene is seen from.
struct FrameView {
    std::uint32_t number = 0;
    CameraPose camera;
    double fovDegrees = 60.0;
};

// The frames of one scene: the plain camera, the turntable's or the path's, cut to --frames.
std::vector<FrameView> framesOf(const Options& options, const Scene& scene,
                                const std::vector<PathCamera>& path) {
    std::vector<FrameView> frames;
    const CameraPose camera = cameraFor(options, scene);
    if (options.turntableFrames > 0) {
        const glm::dvec3 centre = turntableCentre(options, scene, camera);
        const glm::dvec3 axis = turntableAxis(scene, camera);
        note("Turntable: %u frames about the line through %.9g,%.9g,%.9g along %.9g,%.9g,%.9g\n",
             options.turntableFrames, centre.x + 0.0, centre.y + 0.0, centre.z + 0.0, axis.x + 0.0,
             axis.y + 0.0, axis.z + 0.0); // + 0.0: no "-0"
        for (std::uint32_t k = 0; k < options.turntableFrames; ++k)
            frames.push_back({k, turntableFrameCamera(options, scene, camera, centre, axis, k),
                              options.fovDegrees});
    } else if (!path.empty()) {
        for (std::size_t k = 0; k < path.size(); ++k)
            frames.push_back({std::uint32_t(k), path[k].pose, path[k].fovDegrees});
    } else {
        frames.push_back({0, camera, options.fovDegrees});
    }
    if (options.frameRangeGiven)
        std::erase_if(frames, [&](const FrameView& frame) {
            return frame.number < options.frameRange.x || frame.number > options.frameRange.y;
        });
    return frames;
}

// Renders the frames of one loaded scene, each to its file (reserved just before its render,
// and removed again if that render fails). The scene's geometry is released once packed.
void renderScene(const Options& options, const Context& context, KernelCache& kernels, Scene& scene,
                 const std::string& name, const std::vector<FrameView>& frames) {
    RenderSettings settings = renderSettingsFrom(options);
    settings.terminatorFix = terminatorFixFor(options, scene);
    settings.floatOutput = holdsFloats(*outputFormatOf(options.outputPath));
    Renderer renderer;
    HeadlessTarget target;
    ScopeExit teardown([&] {
        destroyHeadlessTarget(target, context);
        destroyRenderer(renderer, context);
    });
    createRendererReleasingGeometry(renderer, context, scene, settings, &kernels);
    createHeadlessTarget(target, context, renderer, options.regionSide);
    for (const FrameView& frame : frames) {
        const std::filesystem::path output =
            expandOutputPattern(options.outputPath.string(), name, frame.number);
        reservePngOutput(output);
        OnFailure removeOutput([&] { releasePngOutput(output); });
        setCamera(renderer, frame.camera);
        if (scene.lightRig) // an OBJ model's rig follows each frame's camera
            setLights(renderer, context, lightRig(*scene.lightRig, frame.camera));
        setFieldOfView(renderer, frame.fovDegrees);
        renderHeadlessFrame(target, context, renderer,
                            options.quiet      ? ProgressMode::Off
                            : options.progress ? ProgressMode::Always
                                               : ProgressMode::Auto);
        throwIfInterrupted();
        if (settings.floatOutput)
            writeFloatImage(output, readHeadlessFloatImage(target, renderer));
        else
            writeImage8(output, readHeadlessImage(target, renderer), int(options.jpegQuality));
        note("Wrote %s\n", output.c_str());
    }
}

} // namespace

int runBatch(const Options& options) {
    installInterruptHandlers();
    // The path is the same for every scene: read it, and fail on it, before anything else.
    std::vector<PathCamera> path;
    if (!options.cameraPath.empty()) {
        path = loadCameraPath(options.cameraPath);
        if (options.frameRangeGiven && options.frameRange.y >= path.size())
            throw UsageError("--frames " + std::to_string(options.frameRange.x) + "-" +
                             std::to_string(options.frameRange.y) +
                             " goes past the last frame of " + options.cameraPath.string() + ", " +
                             std::to_string(path.size() - 1));
    }
    std::vector<std::filesystem::path> scenes = {options.scenePath};
    scenes.insert(scenes.end(), options.moreScenes.begin(), options.moreScenes.end());

    Context context;
    KernelCache kernels;
    ScopeExit teardown([&] {
        destroyKernelCache(kernels, context);
        destroyContext(context);
    });
    openHeadlessDevice(context, options);
    SceneCapacity capacity = sceneCapacityOf(context, !options.storageReads,
                                             options.kernel.precision == Precision::Fp64);
    allowTriangleLayouts(capacity, options.triangleLayout);

    int failed = 0;
    std::uint32_t images = 0;
    for (const std::filesystem::path& scenePath : scenes) {
        Scene scene;
        try {
            scene = loadScene(scenePath, objSceneSetup(options), &capacity);
        } catch (const SceneError& error) {
            std::cerr << error.what() << '\n';
            ++failed;
            continue;
        } catch (const CapacityError& error) { // the next scene may fit
            std::cerr << "error: " << error.what() << '\n';
            ++failed;
            continue;
        }
        for (const std::string& line : loadMessages(scene, scenePath.string()))
            note("%s\n", line.c_str());
        const std::vector<FrameView> frames = framesOf(options, scene, path);
        renderScene(options, context, kernels, scene, scenePath.stem().string(), frames);
        images += std::uint32_t(frames.size());
    }
    const std::string notLoaded =
        failed > 0 ? ", " + std::to_string(failed) + " scene(s) not loaded" : "";
    note("Batch: %u image(s) of %zu scene(s)%s; kernels compiled %u, reused %u\n", images,
         scenes.size() - std::size_t(failed), notLoaded.c_str(), kernels.compiled, kernels.reused);
    return failed;
}
