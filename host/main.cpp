// Raytracer: arguments to a mode (help, headless PNG, benchmark, window), inside
// one try/catch that turns every failure into a message and an exit status.
#include "base/notes.h"
#include "base/output_format.h"
#include "base/parallel.h"
#include "base/phase_progress.h"
#include "base/scope_guard.h"
#include "batch.h"
#include "bench.h"
#include "cli/options.h"
#include "cli/output_pattern.h"
#include "cli/render_settings.h"
#include "cli/version.h"
#include "compare/compare_report.h"
#include "compare/comparison.h"
#include "compare_command.h"
#include "gpu/cpu_driver.h"
#include "gpu/device_list.h"
#include "gpu/limit_overrides.h"
#include "model/scene_file.h"
#include "render/headless.h"
#include "render/interrupt.h"
#include "render/kernel_sources.h"
#include "render/pixel_story.h"
#include "scene/scene_loader.h"
#include "scene/scene_summary.h"
#include "scene/scene_writer.h"
#include "window/window.h"

#include <chrono>
#include <iostream>
#include <unistd.h>

namespace {

// Exit statuses (listed in the README).
enum ExitStatus {
    kSuccess = 0,
    kRuntimeFailure = 1,    // Vulkan, device, shader or file output failure
    kUsageError = 2,        // the command line makes no sense
    kSceneError = 3,        // the scene file is missing or malformed
    kValidationFailure = 4, // --validate and the validation layer printed a message
    kInterrupted = 128      // + the signal: 130 for SIGINT (Ctrl-C), 143 for SIGTERM
};

// --pixel: the story of that pixel as JSON on stdout (host/render/pixel_story.h), after
// the frame when one was rendered (the output image is then in TRANSFER_SRC_OPTIMAL).
void printPixelStory(const Options& options, Renderer& renderer, const Context& context,
                     bool frameRendered) {
    const gpu::GpuPixelStory story = tracePixelStory(
        renderer, context, options.pixel.x, options.pixel.y,
        frameRendered ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED);
    const StoryHeader header{
        options.scenePath.string(), options.pixel.x, options.pixel.y, options.width, options.height,
        options.samplesPerPixel,    options.depth};
    std::cout << pixelStoryJson(story, renderer.sources, header) << std::flush;
}

// --list-devices: every device on stdout, numbered as --device counts them.
void listDevices(const Options& options) {
    Context context;
    ScopeExit teardown([&] { destroyContext(context); });
    createInstance(context, {}, options.validate);
    std::cout << deviceListing(context.instance);
}

// Renders headless: one frame to options.outputPath (PNG, JPEG, PPM, or PFM/EXR floats; "-":
// a PNG on stdout), a benchmark (with -o, its last frame written too), or (--pixel without
// -o) only the story of one pixel.
// Before any work, the output file is known to be writable (its .tmp exists) and the
// image to fit the device; a failure or Ctrl-C afterwards removes the .tmp again. The
// scene's geometry is released once packed (createRendererReleasingGeometry).
void runHeadless(const Options& options, Scene& scene, const StartupTimes& startup) {
    installInterruptHandlers();
    const bool writing = !options.outputPath.empty();
    const bool toFile = writing && !isStandardOutput(options.outputPath);
    if (writing && !toFile && isatty(STDOUT_FILENO) == 1)
        throw std::runtime_error("-o - writes a PNG to stdout, which is a terminal; redirect it "
                                 "to a file or a pipe");
    if (toFile) reservePngOutput(options.outputPath);
    OnFailure removeOutput([&] {
        if (toFile) releasePngOutput(options.outputPath);
    });
    Context context;
    Renderer renderer;
    HeadlessTarget target;
    ScopeExit teardown([&] { // in reverse order of creation, whatever was made
        destroyHeadlessTarget(target, context);
        destroyRenderer(renderer, context);
        destroyContext(context);
    });
    openHeadlessDevice(context, options);
    RenderSettings settings = renderSettingsFrom(options);
    settings.camera = cameraFor(options, scene);
    settings.terminatorFix = terminatorFixFor(options, scene);
    // -o out.pfm|out.exr: the averages before the 8-bit rounding (docs/accuracy.md).
    settings.floatOutput = writing && holdsFloats(*outputFormatOf(options.outputPath));
    createRendererReleasingGeometry(renderer, context, scene, settings);
    createHeadlessTarget(target, context, renderer, options.regionSide);
    if (options.benchFrames > 0)
        std::cout << runBenchmark(context, renderer, target, options, startup) << std::endl;
    else if (writing)
        renderHeadlessFrame(target, context, renderer,
                            options.quiet      ? ProgressMode::Off
                            : options.progress ? ProgressMode::Always
                                               : ProgressMode::Auto);
    if (writing) { // the frame just rendered, or the benchmark's last
        throwIfInterrupted();
        if (settings.floatOutput)
            writeFloatImage(options.outputPath, readHeadlessFloatImage(target, renderer));
        else
            writeImage8(options.outputPath, readHeadlessImage(target, renderer),
                        int(options.jpegQuality));
    }
    if (options.pixelGiven) printPixelStory(options, renderer, context, writing);
}

int run(int argc, char** argv, std::chrono::steady_clock::time_point processStart) {
    StartupTimes startup{processStart, 0.0};
    Options options = parseOptions(argc, argv);
    setQuiet(options.quiet);
    // The start-up's phases report as renders do; a benchmark's stderr stays quiet.
    setPhaseProgressMode(options.benchFrames > 0 || options.benchWindowFrames > 0
                             ? ProgressMode::Off
                         : options.progress ? ProgressMode::Always
                                            : ProgressMode::Auto);
    requestCpuDriverThreads(options.cpuThreads); // before any Vulkan call reads it
    setLimitOverrides({options.maxStorageRange, options.maxAllocation, options.maxImageSide});
    setWorkerThreads(options.cpuThreads); // the host's own threads, the same count
    if (options.showHelp) {
        std::cout << usageText();
        return kSuccess;
    }
    if (options.showVersion) { // before any Vulkan call: it works with no driver at all
        std::cout << versionText();
        return kSuccess;
    }
    if (options.listDevices) {
        listDevices(options);
        return kSuccess;
    }
    if (!options.dumpShadersTo.empty()) {
        writeEmbeddedShaders(options.dumpShadersTo);
        note("Wrote the shader sources to %s; edit them there and run with --shader-dir %s\n",
             options.dumpShadersTo.c_str(), options.dumpShadersTo.c_str());
        if (options.scenePath.empty()) return kSuccess;
    }
    // --validate: any message of the layer fails the run, whatever else it did.
    auto validated = [&](int status) {
        if (options.validate && validationMessageCount() > 0) {
            std::cerr << "error: the validation layer printed " << validationMessageCount()
                      << " message(s)\n";
            return int(kValidationFailure);
        }
        return status;
    };
    if (isBatch(options)) return validated(runBatch(options) > 0 ? kSceneError : kSuccess);
    // One image: a pattern's {name} is the scene's stem, {frame} 0.
    if (!options.outputPath.empty())
        options.outputPath =
            expandOutputPattern(options.outputPath.string(), options.scenePath.stem().string(), 0);
    // --compare: the window takes the image's size (read first: its errors come first).
    std::optional<HandedInImage> compared;
    if (!options.compareImage.empty()) {
        compared = readHandedInImage(options.compareImage);
        options.width = std::uint32_t(compared->levels.width);
        options.height = std::uint32_t(compared->levels.height);
    }
    // A scene that will be rendered is checked against the device as soon as its size is
    // known; one only checked or converted is not.
    const bool converting =
        options.checkOnly ||
        (!options.saveScenePath.empty() && options.outputPath.empty() && options.benchFrames == 0 &&
         !options.pixelGiven && !options.forceWindow && options.benchWindowFrames == 0);
    const std::optional<SceneCapacity> capacity =
        converting ? std::nullopt : capacityBeforeLoading(options);
    const auto parseStart = std::chrono::steady_clock::now();
    Scene scene =
        loadScene(options.scenePath, objSceneSetup(options), capacity ? &*capacity : nullptr);
    startup.parseMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - parseStart)
            .count();
    for (const std::string& line : loadMessages(scene, options.scenePath.string()))
        note("%s\n", line.c_str());
    if (!options.saveScenePath.empty()) {
        writeSceneFile(options.saveScenePath, scene);
        if (const std::string unwritten = unwrittenNote(scene, options.scenePath.string());
            !unwritten.empty())
            note("%s\n", unwritten.c_str());
        note("Wrote %s\n", options.saveScenePath.string().c_str());
        if (converting && !options.checkOnly) return kSuccess;
    }
    if (options.checkOnly) { // the scene parsed: it is valid; no Vulkan from here either
        std::cout << options.scenePath.string() << ": valid\n" << sceneSummary(scene);
        return kSuccess;
    }

    // The comparison as Raytracer compare makes it, its report on stdout; the window shows it.
    std::optional<Comparison> comparison;
    if (compared) {
        comparison = compareWithReference(options.compareImage, std::move(*compared),
                                          options.scenePath, scene, CompareRequest{});
        std::cout << compareText(*comparison) << std::flush;
    }
    bool headless = !options.outputPath.empty() || options.benchFrames > 0 || options.pixelGiven;
    if (!headless && !runWindow(options, scene, comparison ? &*comparison : nullptr)) {
        if (comparison)
            throw std::runtime_error("--compare shows the comparison in a window, but none can be "
                                     "opened: " +
                                     windowUnavailableReason() +
                                     " (the report above is Raytracer compare's)");
        if (options.forceWindow)
            throw std::runtime_error("--window was given, but no window can be opened: " +
                                     windowUnavailableReason());
        if (options.benchWindowFrames > 0)
            throw std::runtime_error("--bench-window needs a display: " +
                                     windowUnavailableReason());
        // Never over an earlier render: test1.png, else test1-1.png, test1-2.png, ...
        const std::filesystem::path wanted = options.scenePath.stem().string() + ".png";
        options.outputPath = firstUnusedName(wanted);
        if (options.outputPath == wanted)
            note("No display: rendering headless to %s\n", wanted.c_str());
        else
            note("No display: rendering headless to %s (%s exists and is kept)\n",
                 options.outputPath.c_str(), wanted.c_str());
        headless = true;
    }
    if (headless) runHeadless(options, scene, startup);
    if (headless && options.benchFrames == 0 && !options.outputPath.empty())
        note("Wrote %s\n", isStandardOutput(options.outputPath) ? "the PNG to stdout"
                                                                : options.outputPath.c_str());

    return validated(kSuccess);
}

} // namespace

int main(int argc, char** argv) {
    const auto processStart = processStartTime();
    const bool compare = argc >= 2 && std::string(argv[1]) == "compare";
    try {
        if (compare) return runCompareCommand(std::vector<std::string>(argv + 2, argv + argc));
        return run(argc, argv, processStart);
    } catch (const UsageError& error) {
        // One line to the help, not the help itself, so that the error stays on screen.
        std::cerr << "error: " << error.what() << "\n"
                  << (compare ? "Run 'Raytracer compare --help' for its options.\n" : kSeeHelp);
        return kUsageError;
    } catch (const SceneError& error) {
        std::cerr << error.what() << '\n';
        return kSceneError;
    } catch (const Interrupted& interruption) {
        std::cerr << "\nnote: " << interruption.what() << '\n';
        return kInterrupted + interruption.signalNumber;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return kRuntimeFailure;
    }
}
