#include "cli/option_checks.h"

#include "base/output_format.h"
#include "cli/output_pattern.h"
#include "scene/file_format.h"

#include <filesystem>
#include <string>
#include <vector>

namespace {

// Options that shape a model (docs/models.md) given with scene files alone: they would
// change nothing, so the command line is not what its writer meant.
void checkModelOptions(const Options& options, const std::vector<std::string>& modelOnly) {
    if (modelOnly.empty() || options.scenePath.empty()) return;
    if (isModelPath(options.scenePath)) return;
    for (const std::filesystem::path& scene : options.moreScenes)
        if (isModelPath(scene)) return;
    std::string flags;
    for (std::size_t i = 0; i < modelOnly.size(); ++i)
        flags += (i == 0 ? "" : i + 1 == modelOnly.size() ? " and " : ", ") + modelOnly[i];
    throw UsageError(flags + " shape" + (modelOnly.size() == 1 ? "s" : "") + " a model, and " +
                     options.scenePath.string() +
                     " is a scene file, whose own triangles, lights and camera are used as "
                     "they are");
}

// The checks of a batch (several scenes, --turntable, --camera-path) and of -o as a
// pattern or a folder, once every option is known; a folder becomes its pattern.
void checkBatch(Options& options) {
    const bool frames = options.turntableFrames > 0 || !options.cameraPath.empty();
    const std::string output = options.outputPath.string();
    // An existing folder is the batch's folder; for one image it stays the error it was
    // (a folder where a file name was meant), unless written as a folder, out/.
    if (!output.empty() && (output.back() == '/' || (isBatch(options) && isOutputFolder(output))))
        options.outputPath = folderOutputPattern(options.outputPath, frames);
    else if (!output.empty() && isOutputFolder(output) && !outputFormatOf(output))
        throw UsageError("-o " + output + ": the output must be a file name ending in " +
                         kOutputNames);
    if (std::string problem = outputPatternProblem(options.outputPath.string()); !problem.empty())
        throw UsageError("-o " + output + ": " + problem);
    if (!isBatch(options)) {
        if (options.frameRangeGiven)
            throw UsageError("--frames chooses frames of --turntable or --camera-path; neither "
                             "was given");
        return;
    }
    if (options.orbitCenter && options.turntableFrames == 0)
        throw UsageError("--orbit-center sets the point --turntable orbits; give --turntable N");
    if (options.turntableFrames > 0 && !options.cameraPath.empty())
        throw UsageError("--turntable and --camera-path both give the frames' cameras; give one");
    if (options.benchFrames > 0 || options.benchWindowFrames > 0 || options.pixelGiven ||
        options.checkOnly || options.forceWindow || !options.saveScenePath.empty())
        throw UsageError("several scenes, --turntable and --camera-path render headless, one "
                         "image after another, and cannot be combined with --bench, "
                         "--bench-window, --pixel, --check, --save-scene or --window");
    const std::string pattern = options.outputPath.string();
    if (isStandardOutput(options.outputPath))
        throw UsageError("-o - writes one PNG to stdout; several scenes, --turntable and "
                         "--camera-path write files: give -o a pattern or a folder");
    if (!options.moreScenes.empty() && pattern.empty()) {
        // Raytracer scene.scene out.png: an output meant, written without -o.
        for (const std::filesystem::path& scene : options.moreScenes) {
            std::error_code error;
            if (std::filesystem::exists(scene, error)) continue;
            throw UsageError("'" + scene.string() +
                             "' is no file: each argument without an option is a scene to "
                             "render" +
                             (outputFormatOf(scene)
                                  ? "; to write the image there, give -o " + scene.string()
                                  : std::string()));
        }
    }
    if (!options.moreScenes.empty() && (pattern.empty() || !outputPatternHas(pattern, "name")))
        throw UsageError(
            "several scenes would all write " + (pattern.empty() ? "no file" : pattern) +
            ": give -o a pattern with {name}, the scene file's stem (out/{name}.png), or a "
            "folder (out/)");
    const bool manyFrames = options.turntableFrames > 1 || !options.cameraPath.empty();
    const std::string framesFlag = options.turntableFrames > 0
                                       ? "--turntable " + std::to_string(options.turntableFrames)
                                       : std::string("--camera-path");
    if (manyFrames && (pattern.empty() || !outputPatternHas(pattern, "frame")))
        throw UsageError(
            framesFlag + " renders frames, but -o " +
            (pattern.empty() ? std::string("is not given") : pattern + " has no {frame}") +
            ": give a pattern such as out/frame-{frame:04}.png");
    if (pattern.empty()) throw UsageError(framesFlag + " renders headless: give -o");
    if (options.frameRangeGiven && options.turntableFrames > 0 &&
        options.frameRange.y >= options.turntableFrames)
        throw UsageError("--frames " + std::to_string(options.frameRange.x) + "-" +
                         std::to_string(options.frameRange.y) + " goes past the last frame of " +
                         framesFlag + ", " + std::to_string(options.turntableFrames - 1));
    if (!options.cameraPath.empty() &&
        (options.cameraTargetGiven || options.camera != CameraPose{} || options.fovDegrees != 60.0))
        throw UsageError("--camera-path gives every frame's camera and field of view; it cannot "
                         "be combined with --camera-pos, --camera-target, --camera-up or --fov");
    // Two scenes of one stem would write the same files.
    if (outputPatternHas(pattern, "name")) {
        std::vector<std::filesystem::path> scenes = {options.scenePath};
        scenes.insert(scenes.end(), options.moreScenes.begin(), options.moreScenes.end());
        for (std::size_t i = 0; i < scenes.size(); ++i)
            for (std::size_t j = i + 1; j < scenes.size(); ++j)
                if (scenes[i].stem() == scenes[j].stem())
                    throw UsageError("'" + scenes[i].string() + "' and '" + scenes[j].string() +
                                     "' are both named '" + scenes[i].stem().string() +
                                     "' and would write the same files");
    }
}

} // namespace

void checkOptionCombinations(Options& options, const OptionsGiven& given) {
    // A target given without a position looks from the origin; a position alone keeps
    // looking down -z from there.
    if (!options.cameraTargetGiven)
        options.camera.target = options.camera.position + glm::dvec3(0.0, 0.0, -1.0);
    if (std::string problem = cameraPoseProblem(options.camera); !problem.empty())
        throw UsageError(problem);
    if (options.scenePath.empty() && !options.showHelp && !options.showVersion &&
        !options.listDevices && options.dumpShadersTo.empty())
        throw UsageError("no scene file given");
    checkModelOptions(options, given.modelOnly);
    if (given.view && !options.fit)
        throw UsageError("--view turns a model fitted to the view, and --no-fit leaves it where "
                         "its file puts it; place the camera with --camera-pos and "
                         "--camera-target instead");
    if (options.forceWindow && (!options.outputPath.empty() || options.benchFrames > 0))
        throw UsageError("--window cannot be combined with -o or --bench, which render headless");
    if (options.pixelGiven &&
        (options.pixel.x >= options.width || options.pixel.y >= options.height))
        throw UsageError("--pixel " + std::to_string(options.pixel.x) + "," +
                         std::to_string(options.pixel.y) + " lies outside the " +
                         std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " image (columns 0 to " + std::to_string(options.width - 1) +
                         ", rows 0 to " + std::to_string(options.height - 1) + ")");
    if (options.pixelGiven &&
        (options.forceWindow || options.benchFrames > 0 || options.benchWindowFrames > 0))
        throw UsageError("--pixel renders headless and cannot be combined with --window, --bench "
                         "or --bench-window (the window's I key prints the story of the pixel "
                         "under the mouse)");
    if (options.checkOnly &&
        (!options.outputPath.empty() || options.benchFrames > 0 || options.benchWindowFrames > 0 ||
         options.pixelGiven || options.forceWindow))
        throw UsageError("--check renders nothing and cannot be combined with -o, --bench, "
                         "--bench-window, --pixel or --window");
    if (!options.snapshotCounts.empty()) {
        if (!options.outputPath.empty() || options.benchFrames > 0 ||
            options.benchWindowFrames > 0 || options.pixelGiven || options.checkOnly)
            throw UsageError("--snapshots writes the window's screenshots and cannot be combined "
                             "with -o, --bench, --bench-window, --pixel or --check");
        if (!options.samplesGiven)
            throw UsageError("--snapshots needs --spp N, the samples per pixel the window "
                             "refines to");
        if (options.snapshotCounts.back() > options.samplesPerPixel)
            throw UsageError("--snapshots " + std::to_string(options.snapshotCounts.back()) +
                             " lies beyond --spp " + std::to_string(options.samplesPerPixel) +
                             ", where the window stops refining");
    }
    if (!options.compareImage.empty() &&
        (!options.outputPath.empty() || options.benchFrames > 0 || options.benchWindowFrames > 0 ||
         options.pixelGiven || options.checkOnly || !options.moreScenes.empty()))
        throw UsageError("--compare opens a window and cannot be combined with -o, --bench, "
                         "--bench-window, --pixel, --check or more scenes (headless: Raytracer "
                         "compare IMAGE SCENE)");
    if (options.benchWindowFrames > 0 && (!options.outputPath.empty() || options.benchFrames > 0))
        throw UsageError(
            "--bench-window cannot be combined with -o or --bench, which render headless");
    if (given.jpegQuality && outputFormatOf(options.outputPath) != OutputFormat::Jpeg)
        throw UsageError("--quality sets a JPEG's quality and needs -o FILE.jpg or FILE.jpeg" +
                         (options.outputPath.empty() ? std::string()
                                                     : ", got -o " + options.outputPath.string()));
    if (isStandardOutput(options.outputPath) && (options.pixelGiven || options.benchFrames > 0))
        throw UsageError("-o - writes the PNG to stdout and cannot be combined with --pixel or "
                         "--bench, which print JSON there");
    if (options.cropGiven) {
        const glm::uvec4 crop = options.crop;
        if (std::uint64_t(crop.x) + crop.z > options.width ||
            std::uint64_t(crop.y) + crop.w > options.height)
            throw UsageError("--crop " + std::to_string(crop.x) + "," + std::to_string(crop.y) +
                             "," + std::to_string(crop.z) + "," + std::to_string(crop.w) +
                             " lies outside the " + std::to_string(options.width) + "x" +
                             std::to_string(options.height) + " image: X+W must be at most " +
                             std::to_string(options.width) + " and Y+H at most " +
                             std::to_string(options.height));
        if (options.outputPath.empty() || options.forceWindow || options.benchWindowFrames > 0)
            throw UsageError("--crop renders a region headless: give -o, and neither --window "
                             "nor --bench-window");
    }
    checkBatch(options);
}
