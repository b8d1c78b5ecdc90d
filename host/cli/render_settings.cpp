// Options to RenderSettings, field by field.
#include "cli/render_settings.h"

#include "gpu/image_limits.h"
#include "gpu/pipeline_cache.h"

RenderSettings renderSettingsFrom(const Options& options) {
    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.samplesPerPixel = options.samplesPerPixel;
    settings.depth = options.depth;
    settings.background = glm::vec3(options.background);
    settings.fovDegrees = options.fovDegrees;
    settings.acceleration = options.acceleration;
    settings.kernel = options.kernel;
    settings.cacheDirectory = userCacheDirectory(options.useCache);
    settings.camera = options.camera;
    settings.shaderDirectory = options.shaderDirectory;
    settings.generalKernel = options.generalKernel;
    settings.countWork = options.countWork;
    settings.storageReads = options.storageReads;
    return settings;
}

void openHeadlessDevice(Context& context, const Options& options) {
    createInstance(context, {}, options.validate);
    createDevice(context, options.device, VK_NULL_HANDLE,
                 options.kernel.precision == Precision::Fp64);
    checkImageFits(imageLimitsOf(context), options.width, options.height, true);
}
