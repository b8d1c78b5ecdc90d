#include "peer_driver.h"

#include "base/json.h"
#include "base/median.h"
#include "model/scene_file.h"
#include "scene/scene_loader.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// Not timed: the first frame faults in memory and warms the caches, as Raytracer's
// warm-up frames let lavapipe compile its shader.
constexpr int warmUpFrames = 1;

const char* const usageText =
    "usage: %s SCENE [-o OUT.png] [--bench N] [--width W] [--height H] [--depth D]\n"
    "          [--spp N] [--threads T]\n"
    "Renders SCENE with the model of docs/model.md on the CPU (a benchmark peer of Raytracer).\n"
    "  -o OUT.png           write the image (with --bench: the last timed frame)\n"
    "  --bench N            render N timed frames after a warm-up, print one JSON line\n"
    "  --width W --height H image size, default 640 480\n"
    "  --depth D            reflection bounces, default 5\n"
    "  --spp N              samples per pixel on a regular grid, default 1\n"
    "  --threads T          worker threads, default 2\n";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

int parseCount(std::string_view option, std::string_view text, int minimum, int maximum) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty() ||
        value < minimum || value > maximum)
        throw UsageError(std::string(option) + " expects a whole number from " +
                         std::to_string(minimum) + " to " + std::to_string(maximum) + ", got '" +
                         std::string(text) + "'");
    return value;
}

// Returns false when --help was given (usage printed).
bool parseOptions(int argc, char** argv, const char* program, PeerOptions& options) {
    for (int k = 1; k < argc; ++k) {
        const std::string_view arg = argv[k];
        auto value = [&]() -> std::string_view {
            if (k + 1 >= argc) throw UsageError(std::string(arg) + " needs a value");
            return argv[++k];
        };
        if (arg == "--help" || arg == "-h") {
            std::printf(usageText, program);
            return false;
        } else if (arg == "-o") {
            options.outputPath = value();
        } else if (arg == "--bench") {
            options.benchFrames = parseCount(arg, value(), 1, 100000);
        } else if (arg == "--width") {
            options.render.width = parseCount(arg, value(), 1, 16384);
        } else if (arg == "--height") {
            options.render.height = parseCount(arg, value(), 1, 16384);
        } else if (arg == "--depth") {
            options.render.depth = parseCount(arg, value(), 0, 64);
        } else if (arg == "--spp") {
            options.render.spp = parseCount(arg, value(), 1, 4096);
        } else if (arg == "--threads") {
            options.threads = parseCount(arg, value(), 1, 1024);
        } else if (arg.starts_with("-")) {
            throw UsageError("unknown option " + std::string(arg));
        } else if (options.scenePath.empty()) {
            options.scenePath = arg;
        } else {
            throw UsageError("more than one scene given");
        }
    }
    if (options.scenePath.empty()) throw UsageError("no scene file given");
    if (options.outputPath.empty() && options.benchFrames == 0)
        throw UsageError("nothing to do: give -o OUT.png, --bench N or both");
    return true;
}

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Timings {
    double parseMs = 0;   // reading the file (the project's parser, as Raytracer's)
    double prepareMs = 0; // the scene in float, positions shared (PeerScene)
    double buildMs = 0;   // the peer's own structures (Embree: the BVH)
    double startupMs = 0; // from main() to the end of the first frame
    std::vector<double> frameMs;
    std::uint64_t raysPerFrame = 0;
};

// Raytracer's --bench keys, with gpu_ms_median and gpu_bytes null (no GPU here), plus
// parse_ms, prepare_ms, build_ms, memory_bytes, threads and the count of every ray traced.
std::string benchJson(const PeerOptions& o, const PeerScene& scene, const PeerRenderer& peer,
                      const Timings& t) {
    const double wallMedian = median(t.frameMs);
    const double seconds = wallMedian * 1e-3;
    const double primary = double(o.render.width) * o.render.height * o.render.spp;
    std::ostringstream json;
    json << "{\"scene\": " << jsonString(o.scenePath.string()) << ", \"width\": " << o.render.width
         << ", \"height\": " << o.render.height << ", \"spp\": " << o.render.spp
         << ", \"depth\": " << o.render.depth << ", \"frames\": " << o.benchFrames
         << ", \"device\": " << jsonString(peer.device)
         << ", \"wall_ms_median\": " << jsonNumber(wallMedian) << ", \"wall_ms_min\": "
         << jsonNumber(*std::min_element(t.frameMs.begin(), t.frameMs.end()))
         << ", \"gpu_ms_median\": null, \"startup_ms\": " << jsonNumber(t.startupMs)
         << ", \"parse_ms\": " << jsonNumber(t.parseMs)
         << ", \"prepare_ms\": " << jsonNumber(t.prepareMs)
         << ", \"build_ms\": " << jsonNumber(t.buildMs)
         << ", \"gpu_bytes\": null, \"memory_bytes\": " << peer.memoryBytes
         << ", \"spheres\": " << scene.spheres.size() << ", \"triangles\": " << scene.fileTriangles
         << ", \"lights\": " << scene.lights.size() << ", \"threads\": " << o.threads
         << ", \"rays_per_frame\": " << t.raysPerFrame
         << ", \"primary_rays_per_second\": " << jsonNumber(primary / seconds)
         << ", \"rays_per_second\": " << jsonNumber(double(t.raysPerFrame) / seconds) << "}";
    return json.str();
}

} // namespace

std::string threadCount(int threads) {
    return std::to_string(threads) + (threads == 1 ? " thread" : " threads");
}

int runPeer(int argc, char** argv, const char* program, const MakePeerRenderer& make) {
    const Clock::time_point processStart = Clock::now();
    PeerOptions options;
    try {
        if (!parseOptions(argc, argv, program, options)) return 0;
    } catch (const UsageError& error) {
        std::fprintf(stderr, "%s: %s (see --help)\n", program, error.what());
        return 2;
    }

    Timings timings;
    Scene scene;
    try {
        const Clock::time_point parseStart = Clock::now();
        scene = loadScene(options.scenePath);
        timings.parseMs = millisecondsSince(parseStart);
    } catch (const SceneError& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 3;
    }
    for (const std::string& warning : scene.warnings)
        std::fprintf(stderr, "%s\n", warning.c_str());

    try {
        const Clock::time_point prepareStart = Clock::now();
        const PeerScene peerScene = makePeerScene(scene);
        scene = Scene(); // the double-precision copy is not needed any more
        timings.prepareMs = millisecondsSince(prepareStart);
        const Clock::time_point buildStart = Clock::now();
        const PeerRenderer peer = make(peerScene, options);
        timings.buildMs = millisecondsSince(buildStart);

        Image8 image;
        timings.raysPerFrame = peer.renderFrame(image);
        timings.startupMs = millisecondsSince(processStart);
        if (options.benchFrames > 0) {
            for (int k = 1; k < warmUpFrames; ++k)
                peer.renderFrame(image);
            for (int k = 0; k < options.benchFrames; ++k) {
                const Clock::time_point frameStart = Clock::now();
                peer.renderFrame(image);
                timings.frameMs.push_back(millisecondsSince(frameStart));
            }
        }
        if (!options.outputPath.empty()) writePng(options.outputPath, image);
        if (options.benchFrames > 0)
            std::printf("%s\n", benchJson(options, peerScene, peer, timings).c_str());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: error: %s\n", program, error.what());
        return 1;
    }
    return 0;
}
