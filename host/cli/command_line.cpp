#include "cli/command_line.h"

#include <cstdio>

namespace {

std::string formatted(const char* pattern, auto... values) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

// %.17g: parseOptions' from_chars reads back the very same double.
std::string exact(double value) {
    return formatted("%.17g", value);
}

std::string triple(const glm::dvec3& v) {
    return exact(v.x) + "," + exact(v.y) + "," + exact(v.z);
}

} // namespace

std::string shellQuoted(const std::string& word) {
    const bool plain =
        !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                                                "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                "0123456789_@%+=:,./-") == std::string::npos;
    if (plain) return word;
    std::string quoted = "'";
    for (char c : word)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string commandLine(const Options& options) {
    const Options defaults;
    std::string command = "Raytracer";
    auto add = [&](const char* flag, const std::string& value) {
        command += std::string(" ") + flag + " " + value;
    };
    auto addPath = [&](const char* flag, const std::filesystem::path& path) {
        if (!path.empty()) add(flag, shellQuoted(path.string()));
    };
    auto addCount = [&](const char* flag, std::uint32_t value, std::uint32_t unless) {
        if (value != unless) add(flag, std::to_string(value));
    };
    auto addSwitch = [&](const char* flag, bool on) {
        if (on) command += std::string(" ") + flag;
    };
    auto addChoice = [&](const char* flag, const auto& names, auto value, auto unless) {
        if (value != unless) add(flag, choiceName(names, value));
    };

    // What changes pixels first, in the order the window's screenshot line has always had.
    if (!options.scenePath.empty()) command += " " + shellQuoted(options.scenePath.string());
    for (const std::filesystem::path& scene : options.moreScenes)
        command += " " + shellQuoted(scene.string());
    addPath("-o", options.outputPath);
    addCount("--quality", options.jpegQuality, defaults.jpegQuality);
    add("--width", std::to_string(options.width));
    add("--height", std::to_string(options.height));
    if (options.samplesGiven || options.samplesPerPixel != defaults.samplesPerPixel)
        add("--spp", std::to_string(options.samplesPerPixel));
    add("--depth", std::to_string(options.depth));
    add("--fov", exact(options.fovDegrees));
    // Without a target parseOptions looks down -z from the position, so the target is
    // written only when it was given; with it, the whole pose.
    const CameraPose &camera = options.camera, plainCamera;
    // A camera given as the default one still stands for the command line's camera (not a
    // fitted model's), so it is said.
    const bool plainGiven = options.cameraGiven && camera == plainCamera;
    if (options.cameraTargetGiven || camera.position != plainCamera.position || plainGiven)
        add("--camera-pos", triple(camera.position));
    if (options.cameraTargetGiven) add("--camera-target", triple(camera.target));
    if (options.cameraTargetGiven || camera.up != plainCamera.up)
        add("--camera-up", triple(camera.up));
    if (options.background != defaults.background) add("--background", triple(options.background));
    if (options.cropGiven)
        add("--crop", std::to_string(options.crop.x) + "," + std::to_string(options.crop.y) + "," +
                          std::to_string(options.crop.z) + "," + std::to_string(options.crop.w));
    const KernelChoices &kernel = options.kernel, &plain = defaults.kernel;
    addChoice("--sampler", samplerNames(), kernel.sampler, plain.sampler);
    addCount("--seed", kernel.seed, plain.seed);
    addChoice("--precision", precisionNames(), kernel.precision, plain.precision);
    addChoice("--sphere-test", sphereTestNames(), kernel.sphereTest, plain.sphereTest);
    addChoice("--triangle-test", triangleTestNames(), kernel.triangleTest, plain.triangleTest);
    addChoice("--offset", rayOffsetNames(), kernel.offset, plain.offset);
    addPath("--shader-dir", options.shaderDirectory);
    if (options.upGiven || options.modelUp != defaults.modelUp)
        add("--up", choiceName(upAxisNames(), options.modelUp));
    if (options.creaseDegrees != defaults.creaseDegrees)
        add("--crease", exact(options.creaseDegrees));
    addSwitch("--no-ground", !options.ground);
    if (options.viewGiven || options.modelView != defaults.modelView)
        add("--view", choiceName(modelViewNames(), options.modelView));
    addSwitch("--no-fit", !options.fit);
    if (options.terminator) add("--terminator", *options.terminator ? "on" : "off");

    // Then how the program runs, which leaves the image as it is.
    addChoice("--accel", accelerationNames(), options.acceleration, defaults.acceleration);
    addChoice("--triangle-layout", triangleLayoutNames(), options.triangleLayout,
              defaults.triangleLayout);
    if (!options.device.empty()) add("--device", shellQuoted(options.device));
    addCount("--threads", options.cpuThreads, 0);
    addCount("--bench", options.benchFrames, 0);
    addCount("--bench-window", options.benchWindowFrames, 0);
    if (!options.snapshotCounts.empty()) {
        std::string counts;
        for (std::uint32_t count : options.snapshotCounts)
            counts += (counts.empty() ? "" : ",") + std::to_string(count);
        add("--snapshots", counts);
    }
    addCount("--region-size", options.regionSide, 0);
    if (options.pixelGiven)
        add("--pixel", std::to_string(options.pixel.x) + "," + std::to_string(options.pixel.y));
    addCount("--turntable", options.turntableFrames, 0);
    if (options.orbitCenter) add("--orbit-center", triple(*options.orbitCenter));
    addPath("--camera-path", options.cameraPath);
    if (options.frameRangeGiven)
        add("--frames",
            std::to_string(options.frameRange.x) + "-" + std::to_string(options.frameRange.y));
    addPath("--dump-shaders", options.dumpShadersTo);
    addPath("--save-scene", options.saveScenePath);
    addSwitch("--validate", options.validate);
    addSwitch("--no-cache", !options.useCache);
    addSwitch("--progress", options.progress);
    addSwitch("--quiet", options.quiet);
    addSwitch("--window", options.forceWindow);
    addSwitch("--overlay", options.overlay);
    addSwitch("--redraw-continuously", options.redrawContinuously);
    addSwitch("--general-kernel", options.generalKernel);
    addSwitch("--count-work", options.countWork);
    addSwitch("--storage-reads", options.storageReads);
    addCount("--max-storage-range", options.maxStorageRange, 0);
    addCount("--max-allocation", options.maxAllocation, 0);
    addCount("--max-image-side", options.maxImageSide, 0);
    addSwitch("--help", options.showHelp);
    addSwitch("--version", options.showVersion);
    addSwitch("--check", options.checkOnly);
    addSwitch("--list-devices", options.listDevices);
    return command;
}

std::string headlessCommand(const Options& options, const CameraPose& camera, int width, int height,
                            std::uint32_t spp) {
    Options view; // only what changes pixels is carried over
    view.scenePath = options.scenePath;
    view.outputPath = "OUT.png";
    view.width = std::uint32_t(width);
    view.height = std::uint32_t(height);
    view.samplesPerPixel = spp;
    view.samplesGiven = true;
    view.depth = options.depth;
    view.fovDegrees = options.fovDegrees;
    view.camera = camera;
    view.cameraTargetGiven = view.cameraGiven = true; // the window's pose is a whole one
    view.background = options.background;
    view.kernel = options.kernel;
    view.shaderDirectory = options.shaderDirectory;
    view.modelUp = options.modelUp; // an OBJ model is built by these
    view.upGiven = options.upGiven;
    view.creaseDegrees = options.creaseDegrees;
    view.ground = options.ground;
    view.modelView = options.modelView;
    view.viewGiven = options.viewGiven;
    view.fit = options.fit;
    view.terminator = options.terminator;
    return commandLine(view);
}
