#include "cli/options.h"

#include "base/output_format.h"
#include "cli/option_checks.h"
#include "cli/option_suggestion.h"
#include "cli/option_values.h"
#include "cli/output_pattern.h"
#include "cli/window_keys.h"

#include "shared.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <string_view>
#include <vector>

namespace {

void noteModelOnly(OptionsGiven& given, const std::string& flag) {
    if (std::find(given.modelOnly.begin(), given.modelOnly.end(), flag) == given.modelOnly.end())
        given.modelOnly.push_back(flag);
}

// Parses one of the kernel's method and precision flags into kernel; false if arg is none.
bool parseKernelOption(const std::string& arg, const std::function<const std::string&()>& value,
                       KernelChoices& kernel) {
    if (arg == "--sampler")
        kernel.sampler = parseChoice(arg, value(), samplerNames());
    else if (arg == "--seed")
        kernel.seed = parseCount(arg, value(), 0, 4294967295u);
    else if (arg == "--precision")
        kernel.precision = parseChoice(arg, value(), precisionNames());
    else if (arg == "--sphere-test")
        kernel.sphereTest = parseChoice(arg, value(), sphereTestNames());
    else if (arg == "--triangle-test")
        kernel.triangleTest = parseChoice(arg, value(), triangleTestNames());
    else if (arg == "--offset")
        kernel.offset = parseChoice(arg, value(), rayOffsetNames());
    else
        return false;
    return true;
}

} // namespace

const ChoiceNames<UpAxis>& upAxisNames() {
    static const ChoiceNames<UpAxis> names = {{"y", UpAxis::PosY}, {"-y", UpAxis::NegY},
                                              {"z", UpAxis::PosZ}, {"-z", UpAxis::NegZ},
                                              {"x", UpAxis::PosX}, {"-x", UpAxis::NegX}};
    return names;
}

const ChoiceNames<ModelView>& modelViewNames() {
    static const ChoiceNames<ModelView> names = {{"three-quarter", ModelView::ThreeQuarter},
                                                 {"front", ModelView::Front},
                                                 {"back", ModelView::Back},
                                                 {"left", ModelView::Left},
                                                 {"right", ModelView::Right},
                                                 {"top", ModelView::Top},
                                                 {"bottom", ModelView::Bottom}};
    return names;
}

UpAxis parseUpAxis(const std::string& flag, const std::string& text) {
    std::string_view axis = text;
    const bool negative = !axis.empty() && axis[0] == '-';
    if (!axis.empty() && (axis[0] == '-' || axis[0] == '+')) axis.remove_prefix(1);
    if (axis.size() == 1) {
        const char letter = static_cast<char>(axis[0] | 0x20); // ASCII lower case
        if (letter == 'x') return negative ? UpAxis::NegX : UpAxis::PosX;
        if (letter == 'y') return negative ? UpAxis::NegY : UpAxis::PosY;
        if (letter == 'z') return negative ? UpAxis::NegZ : UpAxis::PosZ;
    }
    throw UsageError(flag +
                     " expects an axis, x, y or z in either case with an optional sign "
                     "(z, Z, +z, -y), got '" +
                     text + "'");
}

ModelSceneSetup objSceneSetup(const Options& options) {
    ModelSceneSetup setup;
    setup.up = options.modelUp;
    setup.upGiven = options.upGiven;
    setup.creaseDegrees = options.creaseDegrees;
    setup.ground = options.ground;
    setup.view = options.modelView;
    setup.insideWhenEnclosed = !options.viewGiven;
    setup.fit = options.fit;
    setup.fovDegrees = options.fovDegrees;
    setup.aspect = double(options.width) / double(options.height);
    setup.camera = options.camera; // a batch's frames place the rig again for their cameras
    setup.cameraGiven = options.cameraGiven;
    return setup;
}

const ChoiceNames<Acceleration>& accelerationNames() {
    static const ChoiceNames<Acceleration> names = {
        {"auto", Acceleration::Auto}, {"bvh", Acceleration::Bvh}, {"none", Acceleration::None}};
    return names;
}

const ChoiceNames<TriangleLayout>& triangleLayoutNames() {
    static const ChoiceNames<TriangleLayout> names = {{"auto", TriangleLayout::Auto},
                                                      {"corners", TriangleLayout::Corners},
                                                      {"indexed", TriangleLayout::Indexed}};
    return names;
}

std::string usageText() {
    return "Usage: Raytracer SCENE [options]\n"
           "       Raytracer SCENE... -o 'out/{name}.png' [options]\n"
           "       Raytracer compare IMAGE SCENE [options]   (Raytracer compare --help)\n"
           "Renders SCENE in a window (headless to a PNG when there is no display: STEM.png,\n"
           "or STEM-1.png, STEM-2.png, ... beside an earlier one, which is kept). SCENE is a\n"
           "scene file, or a Wavefront OBJ model (.obj, with its MTL materials). Several\n"
           "scenes, --turntable and --camera-path render a batch headless (docs/batches.md).\n"
           "compare checks an image made by another ray tracer against the reference\n"
           "(docs/compare.md).\n"
           "\n"
           "  -o, --output FILE     render headless and write FILE: .png, .jpg/.jpeg or .ppm\n"
           "                        (8-bit), or .pfm or .exr (float: each pixel before the\n"
           "                        8-bit rounding); -o - writes a PNG to stdout\n"
           "  --quality Q           JPEG quality, 1 to 100 (default 90); a .jpg output only\n"
           "  --width W             image width in pixels (default 640)\n"
           "  --height H            image height in pixels (default 480)\n"
           "  --spp N               samples per pixel (default 1: the pixel centre)\n"
           "  --sampler grid|stratified|r2  sample positions for --spp > 1 (default r2: low\n"
           "                        discrepancy, and sample s does not depend on N)\n"
           "  --seed N              varies the stratified jitter and the r2 rotation (default 0)\n"
           "  --precision fp32|fp64  geometry arithmetic in float or double (default fp32;\n"
           "                        fp64 needs a device with shaderFloat64)\n"
           "  --sphere-test naive|stable  ray/sphere test: textbook quadratic, or Ray\n"
           "                        Tracing Gems ch. 7 (default stable)\n"
           "  --triangle-test mt|watertight  ray/triangle test: Moller-Trumbore, or Woop,\n"
           "                        Benthin and Wald 2013 (default watertight)\n"
           "  --offset fixed|scaled|error-bound  secondary-ray origins: 1e-4 along the\n"
           "                        normal, Waechter-Binder scale-relative, or the hit point's\n"
           "                        rounding-error bound (default error-bound)\n"
           "  --depth D             reflection bounces after the primary hit, 0 to " +
           std::to_string(MAX_DEPTH) +
           " (default 5)\n"
           "  --background R,G,B    colour of rays that hit nothing (default 1,1,1)\n"
           "  --fov DEG             vertical field of view in degrees (default 60)\n"
           "  --camera-pos X,Y,Z    eye position (default 0,0,0, the default camera)\n"
           "  --camera-target X,Y,Z point looked at (default 0,0,-1 from the eye: down -z)\n"
           "  --camera-up X,Y,Z     up direction (default 0,1,0)\n"
           "  --bench N             render N frames headless after a warm-up, print JSON timings\n"
           "                        (with -o, the last frame is written too)\n"
           "  --pixel X,Y           print the ray tree of pixel X,Y (column, row) as the kernel\n"
           "                        traced it, as JSON on stdout; headless; alone without -o\n"
           "  --crop X,Y,W,H        render only that region of the full image: W x H pixels, each\n"
           "                        as the full render has it (tools/stitch joins regions)\n"
           "  --turntable N         N frames orbiting about the camera's up axis at its distance\n"
           "                        and height, round the camera's target if given, a model's\n"
           "                        centre, else the centre of what the camera sees; frame 0 is\n"
           "                        the camera\n"
           "  --orbit-center X,Y,Z  the point --turntable orbits instead\n"
           "  --camera-path FILE    a frame per line of FILE: POSITION TARGET UP FOV, as in\n"
           "                        0,0,0 0,0,-1 0,1,0 60 (# comments and blank lines allowed)\n"
           "  --frames FIRST-LAST   only those frames of --turntable or --camera-path (or one: K)\n"
           "  -o patterns           {name}: the scene file's stem; {frame}, {frame:04}: the frame\n"
           "                        number (zero-padded); a folder out/ is out/{name}.png\n"
           "  --device NAME|INDEX   use this Vulkan device (default: a real GPU before a CPU one)\n"
           "  --list-devices        print every Vulkan device (index, name, type, driver, fp64,\n"
           "                        limits) and exit; --device takes the index or the name\n"
           "  --threads N           threads of the host's work (loading, the hierarchy) and of a\n"
           "                        CPU device (lavapipe) (default: one per core)\n"
           "  --accel auto|bvh|none  bounding volume hierarchy, or test every primitive (default\n"
           "                        auto: the hierarchy from " +
           std::to_string(kBvhAutoThreshold) +
           " primitives up)\n"
           "  --triangle-layout auto|corners|indexed  triangles on the GPU as three corner\n"
           "                        positions each (fastest), or as vertex indices and shared\n"
           "                        positions (fewer bytes); same image (default auto: corners\n"
           "                        unless they do not fit or crowd the device's memory)\n"
           "  --validate            enable the Khronos validation layer; any message fails the "
           "run\n"
           "  --no-cache            neither read nor write the shader cache "
           "($XDG_CACHE_HOME/raytracer)\n"
           "  --progress            report progress on stderr even for a render under a second\n"
           "  --quiet               print no progress, notes or warnings on stderr; errors only\n"
           "  --window              show a window or fail; never fall back to a headless PNG\n"
           "  --overlay             open the window with its overlay shown (H toggles it)\n"
           "  --compare FILE        window: compare the render with FILE, another tracer's image\n"
           "                        of the scene (as Raytracer compare does): 1, 2, 3 show the\n"
           "                        render, FILE, the difference; I prints a pixel's diagnosis\n"
           "  --shader-dir DIR      compile the kernel from DIR's sources (trace.comp and its\n"
           "                        includes); the window recompiles when one is saved\n"
           "  --dump-shaders DIR    write the built-in shader sources to DIR and exit\n"
           "  --bench-window N      window: time N progressive frames, print frames per second\n"
           "  --snapshots K,K,...   window: write a screenshot, as P does, when refinement "
           "reaches\n"
           "                        each of these samples per pixel (at most --spp N)\n"
           "  --up AXIS             an OBJ model's axis that is up: x, y or z, either case,\n"
           "                        optionally signed (z, Z, +z, -y; default y)\n"
           "  --crease DEG          an OBJ model's corners without normals average the faces\n"
           "                        around them within DEG degrees of their own (0: flat, 180:\n"
           "                        smooth everywhere; default 60)\n"
           "  --no-ground           no floor under an OBJ model\n"
           "  --view NAME           the side a fitted OBJ model is seen from: three-quarter\n"
           "                        (default: front right, from above), front, back, left,\n"
           "                        right, top, bottom\n"
           "  --no-fit              an OBJ model stays where its file puts it, in its units\n"
           "  --terminator on|off   shadow rays leave smooth-shaded triangles from the hit point\n"
           "                        moved onto the vertex normals' tangent planes (Hanika), so\n"
           "                        coarse meshes lose their polygonal shadow patches (default:\n"
           "                        on for OBJ models, off for scene files)\n"
           "  --save-scene FILE     write the scene as read (an OBJ model as built: fitted,\n"
           "                        lit, with its normals) in the scene format; alone, nothing\n"
           "                        else is done\n"
           "  --check               parse and validate SCENE without Vulkan: print its counts,\n"
           "                        bounds and warnings; exit 0 if valid, 3 if not\n"
           "  --version             print the version, and those of the Vulkan headers and\n"
           "                        glslang it was built with\n"
           "  -h, --help            show this help\n"
           "\n"
           "The window refines progressively, one or more samples per pixel per frame, up to\n"
           "--spp N if given (then it shows exactly the headless --spp N image), else 1024.\n"
           "Saving the scene file (or a --shader-dir source) re-renders it.\n"
           "\n" +
           windowKeysHelp();
}

Options parseOptions(int argc, const char* const* argv) {
    Options options;
    OptionsGiven given; // what only the flags given, not their values, tell
    std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size(); ++i) {
        // --opt=value is --opt value: arg is then the name, and value() returns the rest
        // (which an option without a value must not be given).
        const std::size_t equals = args[i].find('=');
        const bool hasInlineValue = args[i].compare(0, 2, "--") == 0 && equals != std::string::npos;
        const std::string arg = hasInlineValue ? args[i].substr(0, equals) : args[i];
        const std::string inlineValue = hasInlineValue ? args[i].substr(equals + 1) : "";
        bool inlineValueUsed = false;
        auto value = [&]() -> const std::string& {
            if (hasInlineValue) {
                inlineValueUsed = true;
                return inlineValue;
            }
            if (i + 1 >= args.size()) throw UsageError(arg + " expects a value");
            return args[++i];
        };
        if (arg == "-h" || arg == "--help") {
            options.showHelp = true;
        } else if (arg == "--version") {
            options.showVersion = true;
        } else if (arg == "--check") {
            options.checkOnly = true;
        } else if (arg == "-o" || arg == "--output") {
            options.outputPath = value();
            if (options.outputPath.empty()) throw UsageError(arg + " expects a file name");
            if (!isOutputFolder(options.outputPath) && !outputFormatOf(options.outputPath))
                throw UsageError(arg + " " + options.outputPath.string() +
                                 ": the output must be a file name ending in " + kOutputNames);
        } else if (arg == "--quality") {
            options.jpegQuality = parseCount(arg, value(), 1, 100);
            given.jpegQuality = true;
        } else if (arg == "--save-scene") {
            options.saveScenePath = value();
            if (options.saveScenePath.empty()) throw UsageError(arg + " expects a file name");
        } else if (arg == "--up") {
            options.modelUp = parseUpAxis(arg, value());
            options.upGiven = true;
            noteModelOnly(given, arg);
        } else if (arg == "--crease") {
            noteModelOnly(given, arg);
            const std::string& degrees = value();
            options.creaseDegrees = parseReal(arg, degrees);
            if (!(options.creaseDegrees >= 0.0 && options.creaseDegrees <= 180.0))
                throw UsageError("--crease expects degrees from 0 to 180, got '" + degrees + "'");
        } else if (arg == "--no-ground") {
            options.ground = false;
            noteModelOnly(given, arg);
        } else if (arg == "--view") {
            options.modelView = parseChoice(arg, value(), modelViewNames());
            options.viewGiven = true;
            given.view = true;
            noteModelOnly(given, arg);
        } else if (arg == "--terminator") {
            const std::string& text = value();
            if (text != "on" && text != "off")
                throw UsageError("--terminator expects on or off, got '" + text + "'");
            options.terminator = text == "on";
        } else if (arg == "--no-fit") {
            options.fit = false;
            noteModelOnly(given, arg);
        } else if (arg == "--width") {
            options.width = parseCount(arg, value(), 1, kMaxImageSide);
        } else if (arg == "--height") {
            options.height = parseCount(arg, value(), 1, kMaxImageSide);
        } else if (arg == "--spp") {
            options.samplesPerPixel = parseCount(arg, value(), 1, 65536);
            options.samplesGiven = true;
        } else if (arg == "--depth") {
            options.depth = parseCount(arg, value(), 0, MAX_DEPTH);
        } else if (arg == "--background") {
            options.background = parseColor(arg, value());
        } else if (arg == "--fov") {
            options.fovDegrees = parseReal(arg, value());
            if (!(options.fovDegrees > 0.0 && options.fovDegrees < 180.0))
                throw UsageError("--fov expects degrees strictly between 0 and 180");
        } else if (arg == "--camera-pos") {
            options.camera.position = parseVector(arg, value());
            options.cameraGiven = true;
        } else if (arg == "--camera-target") {
            options.camera.target = parseVector(arg, value());
            options.cameraTargetGiven = options.cameraGiven = true;
        } else if (arg == "--orbit-center" || arg == "--orbit-centre") {
            options.orbitCenter = parseVector(arg, value());
        } else if (arg == "--camera-up") {
            options.camera.up = parseVector(arg, value());
            options.cameraGiven = true;
        } else if (arg == "--shader-dir") {
            options.shaderDirectory = value();
            std::error_code error;
            if (!std::filesystem::is_regular_file(options.shaderDirectory / "trace.comp", error))
                throw UsageError(
                    "--shader-dir expects a folder holding trace.comp (see --dump-shaders), got '" +
                    options.shaderDirectory.string() + "'");
        } else if (arg == "--dump-shaders") {
            options.dumpShadersTo = value();
            if (options.dumpShadersTo.empty()) throw UsageError("--dump-shaders expects a folder");
        } else if (arg == "--bench-window") {
            options.benchWindowFrames = parseCount(arg, value(), 1, 100000);
        } else if (arg == "--snapshots") {
            options.snapshotCounts = parseSampleCounts(arg, value());
        } else if (arg == "--bench") {
            options.benchFrames = parseCount(arg, value(), 1, 100000);
        } else if (arg == "--device") {
            options.device = value();
        } else if (arg == "--threads") {
            options.cpuThreads = parseCount(arg, value(), 1, 256);
        } else if (arg == "--accel") {
            options.acceleration = parseChoice(arg, value(), accelerationNames());
        } else if (arg == "--triangle-layout") {
            options.triangleLayout = parseChoice(arg, value(), triangleLayoutNames());
        } else if (arg == "--validate") {
            options.validate = true;
        } else if (arg == "--no-cache") {
            options.useCache = false;
        } else if (arg == "--region-size") {
            options.regionSide = parseCount(arg, value(), 1, 16384);
        } else if (arg == "--list-devices") {
            options.listDevices = true;
        } else if (arg == "--quiet") {
            options.quiet = true;
        } else if (arg == "--progress") {
            options.progress = true;
        } else if (arg == "--window") {
            options.forceWindow = true;
        } else if (arg == "--overlay") {
            options.overlay = true;
        } else if (arg == "--compare") {
            options.compareImage = value();
            if (options.compareImage.empty()) throw UsageError("--compare expects an image file");
        } else if (arg == "--redraw-continuously") {
            options.redrawContinuously = true;
        } else if (arg == "--general-kernel") {
            options.generalKernel = true;
        } else if (arg == "--count-work") {
            options.countWork = true;
        } else if (arg == "--storage-reads") {
            options.storageReads = true;
        } else if (arg == "--max-storage-range") {
            options.maxStorageRange = parseCount(arg, value(), 16, 4294967295u);
        } else if (arg == "--max-allocation") {
            options.maxAllocation = parseCount(arg, value(), 16, 4294967295u);
        } else if (arg == "--max-image-side") {
            options.maxImageSide = parseCount(arg, value(), 1, kMaxImageSide);
        } else if (arg == "--pixel") {
            options.pixel = parsePixel(arg, value());
            options.pixelGiven = true;
        } else if (arg == "--turntable") {
            options.turntableFrames = parseCount(arg, value(), 1, 100000);
        } else if (arg == "--camera-path") {
            options.cameraPath = value();
            if (options.cameraPath.empty()) throw UsageError("--camera-path expects a file name");
        } else if (arg == "--frames") {
            options.frameRange = parseFrameRange(arg, value());
            options.frameRangeGiven = true;
        } else if (arg == "--crop") {
            options.crop = parseCrop(arg, value());
            options.cropGiven = true;
        } else if (parseKernelOption(arg, value, options.kernel)) {
        } else if (arg.size() > 1 && arg[0] == '-') {
            const std::string close = closeOptions(arg, documentedOptions(usageText()));
            throw UsageError("unknown option '" + arg + "'" +
                             (close.empty() ? "" : "; did you mean " + close + "?"));
        } else if (options.scenePath.empty()) {
            options.scenePath = arg;
        } else {
            options.moreScenes.push_back(arg);
        }
        if (hasInlineValue && !inlineValueUsed)
            throw UsageError(arg + " takes no value, got '" + args[i] + "'");
    }
    checkOptionCombinations(options, given);
    return options;
}

bool isBatch(const Options& options) {
    return !options.moreScenes.empty() || options.turntableFrames > 0 ||
           !options.cameraPath.empty();
}
