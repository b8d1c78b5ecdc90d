// Options to RenderSettings, field by field.
#include "cli/render_settings.h"

#include "gpu/image_limits.h"
#include "gpu/limit_overrides.h"
#include "gpu/pipeline_cache.h"
#include "model/model_fit.h"
#include "render/device_capacity.h"

#include <filesystem>

RenderSettings renderSettingsFrom(const Options& options) {
    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.samplesPerPixel = options.samplesPerPixel;
    settings.depth = options.depth;
    settings.background = glm::vec3(options.background);
    settings.fovDegrees = options.fovDegrees;
    settings.acceleration = options.acceleration;
    settings.triangleLayout = options.triangleLayout;
    settings.kernel = options.kernel;
    settings.cacheDirectory = userCacheDirectory(options.useCache);
    settings.camera = options.camera;
    settings.shaderDirectory = options.shaderDirectory;
    settings.generalKernel = options.generalKernel;
    settings.countWork = options.countWork;
    settings.storageReads = options.storageReads;
    if (options.cropGiven)
        settings.crop = {options.crop.x, options.crop.y, options.crop.z, options.crop.w};
    return settings;
}

void openHeadlessDevice(Context& context, const Options& options) {
    createInstance(context, {}, options.validate);
    createDevice(context, options.device, VK_NULL_HANDLE,
                 options.kernel.precision == Precision::Fp64);
    // Only the crop is made (RenderSettings::crop): a poster's part must fit, not the poster.
    if (options.cropGiven) {
        checkImageFits(imageLimitsOf(context), options.crop.z, options.crop.w, true);
        return;
    }
    try {
        checkImageFits(imageLimitsOf(context), options.width, options.height, true);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(std::string(error.what()) +
                                 "; render it in --crop parts that fit, which tools/stitch joins");
    }
}

bool seesModelWithItsCamera(const Options& options, const Scene& scene) {
    return !options.cameraGiven && scene.model && scene.model->fitted;
}

CameraPose cameraFor(const Options& options, const Scene& scene) {
    if (!seesModelWithItsCamera(options, scene)) return options.camera;
    return {glm::dvec3(0.0), scene.model->centre, scene.model->up};
}

glm::dvec3 turntableCentre(const Options& options, const Scene& scene, const CameraPose& camera) {
    if (options.orbitCenter) return *options.orbitCenter;
    if (options.cameraTargetGiven || seesModelWithItsCamera(options, scene)) return camera.target;
    return subjectBounds(scene, camera, options.fovDegrees,
                         double(options.width) / double(options.height))
        .centre;
}

glm::dvec3 turntableAxis(const Scene& scene, const CameraPose& camera) {
    if (scene.model) return glm::normalize(camera.up);
    return floorAxis(scene, camera.up);
}

CameraPose turntableFrameCamera(const Options& options, const Scene& scene,
                                const CameraPose& camera, glm::dvec3 centre, glm::dvec3 axis,
                                std::uint32_t frame) {
    const CameraPose turned = turntableCamera(camera, centre, axis, frame, options.turntableFrames);
    const bool refit = frame > 0 && seesModelWithItsCamera(options, scene) &&
                       !scene.model->inside && !options.orbitCenter && !scene.meshes.empty();
    if (!refit) return turned;
    // The model is the scene's first mesh (its floor, if any, the second).
    return refitCamera(turned, scene.meshes.front().positions, options.fovDegrees,
                       double(options.width) / double(options.height));
}

bool terminatorFixFor(const Options& options, const Scene& scene) {
    return options.terminator.value_or(scene.model.has_value());
}

std::optional<SceneCapacity> capacityBeforeLoading(const Options& options) {
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(options.scenePath, error);
    const LimitOverrides& lowered = limitOverrides();
    const bool limitsLowered = lowered.maxStorageBufferRange || lowered.maxMemoryAllocationSize;
    if (!limitsLowered && (error || bytes < kProbedFileBytes)) return std::nullopt;
    SceneCapacity capacity = probeSceneCapacity(options.device, !options.storageReads,
                                                options.kernel.precision == Precision::Fp64);
    allowTriangleLayouts(capacity, options.triangleLayout);
    return capacity;
}
