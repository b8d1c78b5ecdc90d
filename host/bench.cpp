#include "bench.h"

#include "base/json.h"
#include "base/median.h"
#include "base/startup_phases.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace {

// lavapipe compiles the shader lazily on the first dispatches; these are not timed.
constexpr int kWarmUpFrames = 2;

// The process's start time in seconds since boot (field 22 of /proc/self/stat), or a
// negative value if it cannot be read.
double processStartSecondsSinceBoot() {
    std::ifstream file("/proc/self/stat");
    std::string stat;
    std::getline(file, stat);
    // Field 2, the command name, is in parentheses and may hold spaces: count after it.
    std::size_t close = stat.rfind(')');
    if (close == std::string::npos) return -1.0;
    std::istringstream fields(stat.substr(close + 1));
    std::string field;
    for (int index = 3; index <= 22 && fields >> field; ++index)
        if (index == 22) return double(std::stoull(field)) / double(sysconf(_SC_CLK_TCK));
    return -1.0;
}

// CPU time used so far by every thread of the process (user + system), in ms. On a CPU
// driver such as lavapipe the trace runs on the process's own threads, and their CPU time
// is far less disturbed by other load on the machine than wall time.
double processCpuMilliseconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) * 1e-3; };
    return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// The parts of the kernel compiled out for this scene (traceSpecialization), as a JSON
// list: what --general-kernel keeps in. Empty: the scene needs the general kernel anyway.
std::string compiledOutJson(const TraceSpecialization& specialization) {
    std::string list;
    auto add = [&](VkBool32 present, const char* name) {
        if (!present) list += (list.empty() ? "" : ", ") + jsonString(name);
    };
    add(specialization.hasSpheres, "spheres");
    add(specialization.hasTriangles, "triangles");
    add(specialization.hasSpecular, "highlight");
    add(specialization.hasMirrors, "mirrors");
    return "[" + list + "]";
}

} // namespace

std::chrono::steady_clock::time_point processStartTime() {
    const auto now = std::chrono::steady_clock::now();
    timespec boot{};
    const double started = processStartSecondsSinceBoot();
    // The kernel counts the start time on CLOCK_BOOTTIME.
    if (started < 0 || clock_gettime(CLOCK_BOOTTIME, &boot) != 0) return now;
    const double age = double(boot.tv_sec) + double(boot.tv_nsec) * 1e-9 - started;
    if (age < 0 || age > 60.0)
        return now; // not a plausible age for a process calling this from main()
    return now - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(age));
}

namespace {

// `, "read_ms": 812.3, "model_ms": ...`: the start-up's phases (base/startup_phases.h), in
// the order they ran; flat keys, so that the report stays one object without nesting.
std::string phasesJson() {
    std::string json;
    for (const auto& [name, milliseconds] : recordedPhases())
        json += ", " + jsonString(name + "_ms") + ": " + jsonNumber(milliseconds);
    return json;
}

} // namespace

std::string runBenchmark(const Context& context, Renderer& renderer, HeadlessTarget& target,
                         const Options& options, const StartupTimes& startup) {
    renderHeadlessFrame(target, context, renderer);
    double startupMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                 startup.processStart)
                           .count();
    for (int i = 1; i < kWarmUpFrames; ++i)
        renderHeadlessFrame(target, context, renderer);

    std::vector<double> wallMs, gpuMs;
    std::uint32_t submissions = 0;
    FrameTiming last;
    const double cpuStart = processCpuMilliseconds();
    for (std::uint32_t frame = 0; frame < options.benchFrames; ++frame) {
        FrameTiming timing = renderHeadlessFrame(target, context, renderer);
        wallMs.push_back(timing.wallMs);
        gpuMs.push_back(timing.gpuMs);
        submissions = timing.submissions;
        last = timing;
    }
    const double cpuMsPerFrame = (processCpuMilliseconds() - cpuStart) / options.benchFrames;
    const RenderSettings& settings = renderer.settings;
    const TraceRegion traced = outputRegion(settings); // the crop, or all of the image
    double pixels = double(traced.width) * traced.height;
    double wallMedian = median(wallMs);

    std::ostringstream json;
    json << "{\"scene\": " << jsonString(options.scenePath.string())
         << ", \"width\": " << settings.width << ", \"height\": " << settings.height
         << ", \"spp\": " << settings.samplesPerPixel << ", \"depth\": " << settings.depth
         << ", \"frames\": " << options.benchFrames
         << ", \"device\": " << jsonString(context.properties.deviceName)
         << ", \"wall_ms_median\": " << jsonNumber(wallMedian)
         << ", \"wall_ms_min\": " << jsonNumber(*std::min_element(wallMs.begin(), wallMs.end()))
         << ", \"gpu_ms_median\": "
         << (context.timestampsSupported ? jsonNumber(median(gpuMs)) : "null")
         << ", \"cpu_ms_per_frame\": " << jsonNumber(cpuMsPerFrame)
         << ", \"startup_ms\": " << jsonNumber(startupMs)
         << ", \"parse_ms\": " << jsonNumber(startup.parseMs) << phasesJson()
         << ", \"submissions\": " << submissions << ", \"gpu_bytes\": " << renderer.scene.bytes
         << ", \"texture_bytes\": " << renderer.scene.textureBytes
         << ", \"spheres\": " << renderer.scene.sphereCount
         << ", \"triangles\": " << renderer.scene.triangleCount
         << ", \"lights\": " << renderer.scene.lightCount
         << ", \"sampler\": " << jsonString(choiceName(samplerNames(), settings.kernel.sampler))
         << ", \"seed\": " << settings.kernel.seed << ", \"precision\": "
         << jsonString(choiceName(precisionNames(), settings.kernel.precision))
         << ", \"sphere_test\": "
         << jsonString(choiceName(sphereTestNames(), settings.kernel.sphereTest))
         << ", \"triangle_test\": "
         << jsonString(choiceName(triangleTestNames(), settings.kernel.triangleTest))
         << ", \"offset\": " << jsonString(choiceName(rayOffsetNames(), settings.kernel.offset))
         << ", \"general_kernel\": " << (settings.generalKernel ? "true" : "false")
         << ", \"compiled_out\": " << compiledOutJson(renderer.specialization)
         << ", \"texel_reads\": " << (renderer.specialization.texelReads ? "true" : "false")
         << ", \"triangle_layout\": "
         << jsonString(renderer.specialization.indexedTriangles ? "indexed" : "corners")
         << ", \"baked_spheres\": " << (renderer.specialization.bakedSpheres ? "true" : "false")
         << ", \"primary_rays_per_second\": "
         << jsonNumber(pixels * settings.samplesPerPixel / (wallMedian * 1e-3));
    if (settings.countWork)
        json << ", \"node_visits\": " << last.nodeVisits
             << ", \"leaf_primitive_tests\": " << last.leafPrimitiveTests;
    json << "}";
    return json.str();
}
