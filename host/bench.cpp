#include "bench.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

namespace {

// lavapipe compiles the shader lazily on the first dispatches; these are not timed.
constexpr int kWarmUpFrames = 2;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

std::string jsonString(const std::string& text) {
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') quoted += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            quoted += escaped;
            continue;
        }
        quoted += c;
    }
    return quoted + "\"";
}

std::string jsonNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

} // namespace

std::string runBenchmark(const Context& context, const Renderer& renderer, HeadlessTarget& target,
                         const Options& options, std::chrono::steady_clock::time_point processStart) {
    renderHeadlessFrame(target, context, renderer);
    double startupMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - processStart).count();
    for (int i = 1; i < kWarmUpFrames; ++i) renderHeadlessFrame(target, context, renderer);

    std::vector<double> wallMs, gpuMs;
    for (std::uint32_t frame = 0; frame < options.benchFrames; ++frame) {
        wallMs.push_back(renderHeadlessFrame(target, context, renderer));
        gpuMs.push_back(lastTraceGpuMilliseconds(renderer, context));
    }
    const RenderSettings& settings = renderer.settings;
    double pixels = double(settings.width) * settings.height;
    double wallMedian = median(wallMs);

    std::ostringstream json;
    json << "{\"scene\": " << jsonString(options.scenePath.string())
         << ", \"width\": " << settings.width << ", \"height\": " << settings.height
         << ", \"spp\": " << settings.samplesPerPixel << ", \"depth\": " << settings.depth
         << ", \"frames\": " << options.benchFrames
         << ", \"device\": " << jsonString(context.properties.deviceName)
         << ", \"wall_ms_median\": " << jsonNumber(wallMedian)
         << ", \"wall_ms_min\": " << jsonNumber(*std::min_element(wallMs.begin(), wallMs.end()))
         << ", \"gpu_ms_median\": " << (context.timestampsSupported ? jsonNumber(median(gpuMs)) : "null")
         << ", \"startup_ms\": " << jsonNumber(startupMs)
         << ", \"gpu_bytes\": " << renderer.scene.bytes
         << ", \"spheres\": " << renderer.scene.sphereCount
         << ", \"triangles\": " << renderer.scene.triangleCount
         << ", \"lights\": " << renderer.scene.lightCount
         << ", \"primary_rays_per_second\": "
         << jsonNumber(pixels * settings.samplesPerPixel / (wallMedian * 1e-3)) << "}";
    return json.str();
}
