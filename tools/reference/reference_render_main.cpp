// reference_render SCENE -o out.png [options]: the CPU reference renderer as a tool.
#include "base/output_format.h"
#include "compare/student_model.h"
#include "model/scene_file.h"
#include "reference/reference_renderer.h"
#include "reference/reference_story.h"
#include "scene/scene_loader.h"
#include "tool_arguments.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

const char* const usage =
    "usage: reference_render SCENE -o OUT [--width W] [--height H] [--depth D]\n"
    "                        [--spp N] [--background R,G,B] [--fov DEG] [--truncate]\n"
    "                        [--threads N] [--camera-pos X,Y,Z] [--camera-target X,Y,Z]\n"
    "                        [--camera-up X,Y,Z] [--pixel X,Y] [--mistake NAME]\n"
    "                        [--terminator on|off]\n"
    "Renders SCENE with the double-precision CPU reference (the model of docs/model.md).\n"
    "SCENE may be an OBJ model, built as Raytracer builds it by default (docs/models.md).\n"
    "  -o OUT                 OUT.png: 8-bit; OUT.pfm or OUT.exr: float, each pixel's average\n"
    "                         of clamped samples before the rounding to 8 bits\n"
    "  --width W --height H   image size, default 640 480\n"
    "  --depth D              reflection bounces, default 5\n"
    "  --spp N                samples per pixel on a regular grid, default 1\n"
    "  --background R,G,B     colour of rays that hit nothing, default 1,1,1\n"
    "  --fov DEG              vertical field of view, default 60\n"
    "  --truncate             write floor(c*255) instead of rounding (the course's images;\n"
    "                         PNG only)\n"
    "  --threads N            worker threads, default: one per hardware thread\n"
    "  --camera-pos X,Y,Z     eye position, default 0,0,0\n"
    "  --camera-target X,Y,Z  point looked at, default 0,0,-1 from the eye\n"
    "  --camera-up X,Y,Z      up direction, default 0,1,0\n"
    "  --pixel X,Y            print pixel X,Y's ray tree as JSON on stdout, the fields of\n"
    "                         Raytracer --pixel (docs/pixel_story.md); alone without -o\n"
    "  --mistake NAME         render as a tracer that makes one of the classic mistakes of\n"
    "                         Raytracer compare's catalogue (docs/compare.md), one sample per\n"
    "                         pixel: an image to try compare on; OUT may then also be\n"
    "                         .jpg (stb's encoder) or .ppm\n"
    "  --jpeg-quality Q       with --mistake and OUT.jpg: quality 1 to 100, default 90\n"
    "  --terminator on|off    shadow rays from Hanika's shifted point on smooth-shaded\n"
    "                         triangles, as Raytracer's option; default on for an OBJ model\n";

using tool_arguments::parseCount;
using tool_arguments::parseFov;
using tool_arguments::parseNumber;
using tool_arguments::parseTriple;
using tool_arguments::UsageError;

glm::dvec3 parseColor(std::string_view option, std::string_view text) {
    return parseTriple(option, text, false);
}

// --pixel X,Y: a column and a row, whole numbers from 0.
glm::ivec2 parsePixel(std::string_view option, std::string_view text) {
    const std::size_t comma = text.find(',');
    if (comma == std::string_view::npos)
        throw UsageError(std::string(option) + " expects a pixel X,Y, got '" + std::string(text) +
                         "'");
    const glm::ivec2 pixel(parseNumber<int>(option, text.substr(0, comma)),
                           parseNumber<int>(option, text.substr(comma + 1)));
    if (pixel.x < 0 || pixel.y < 0)
        throw UsageError(std::string(option) + " expects a pixel X,Y from 0,0, got '" +
                         std::string(text) + "'");
    return pixel;
}

// --mistake NAME: a mistake of the catalogue, by its name.
Mistake parseMistake(std::string_view option, std::string_view text) {
    std::string names;
    for (const MistakeDescription& entry : mistakeCatalogue()) {
        if (text == entry.name) return entry.mistake;
        names += std::string(names.empty() ? "" : ", ") + entry.name;
    }
    throw UsageError(std::string(option) + " expects one of " + names + "; got '" +
                     std::string(text) + "'");
}

// The scene as a tracer with mistake renders it: each pixel's colour clamped to [0, 1] (NaN
// to 0, as compare presents it),
// as floats, or as bytes rounded (or truncated) as the reference writes them.
ImageF renderWithMistake(const Scene& scene, const ReferenceSettings& settings, Mistake mistake,
                         int threads, Image8* bytes) {
    std::vector<glm::ivec2> pixels;
    for (int j = 0; j < settings.height; ++j)
        for (int i = 0; i < settings.width; ++i)
            pixels.emplace_back(i, j);
    ReferenceSettings unclamped = settings;
    unclamped.clampSamples = false;
    ImageF image;
    image.width = bytes->width = settings.width;
    image.height = bytes->height = settings.height;
    for (const glm::dvec3& c : studentColours(scene, unclamped, mistake, pixels, threads)) {
        for (int k = 0; k < 3; ++k) {
            const double v = c[k] > 0 ? std::min(c[k], 1.0) : 0.0; // NaN (pow of a negative) too
            image.rgb.push_back(float(v));
            bytes->rgba.push_back(std::uint8_t(quantizeChannel(v, settings.truncate)));
        }
        bytes->rgba.push_back(255);
    }
    return image;
}

} // namespace

int main(int argc, char** argv) {
    std::string scenePath, outputPath;
    ReferenceSettings settings;
    int threads = 0;
    bool targetGiven = false; // else the target follows --camera-pos: looking down -z
    bool pixelGiven = false;
    glm::ivec2 pixel(0);
    bool floatOutput = false; // -o OUT.pfm or OUT.exr
    Mistake mistake = Mistake::None;
    int jpegQuality = kDefaultJpegQuality;
    bool cameraGiven = false;
    std::optional<bool> terminator; // --terminator; unset: on for an OBJ model
    try {
        for (int k = 1; k < argc; ++k) {
            const std::string_view arg = argv[k];
            auto value = [&]() -> std::string_view {
                if (k + 1 >= argc) throw UsageError(std::string(arg) + " needs a value");
                return argv[++k];
            };
            if (arg == "--help" || arg == "-h") {
                std::fputs(usage, stdout);
                return 0;
            } else if (arg == "-o") {
                outputPath = value();
            } else if (arg == "--width") {
                settings.width = parseCount(arg, value(), 1);
            } else if (arg == "--height") {
                settings.height = parseCount(arg, value(), 1);
            } else if (arg == "--depth") {
                settings.depth = parseCount(arg, value(), 0);
            } else if (arg == "--spp") {
                settings.spp = parseCount(arg, value(), 1);
            } else if (arg == "--threads") {
                threads = parseCount(arg, value(), 0);
            } else if (arg == "--background") {
                settings.background = parseColor(arg, value());
            } else if (arg == "--fov") {
                settings.fovDegrees = parseFov(arg, value());
            } else if (arg == "--camera-pos") {
                settings.cameraPosition = parseTriple(arg, value(), true);
                cameraGiven = true;
                if (!targetGiven)
                    settings.cameraTarget = settings.cameraPosition + glm::dvec3(0, 0, -1);
            } else if (arg == "--camera-target") {
                settings.cameraTarget = parseTriple(arg, value(), true);
                targetGiven = cameraGiven = true;
            } else if (arg == "--camera-up") {
                settings.cameraUp = parseTriple(arg, value(), true);
                cameraGiven = true;
            } else if (arg == "--pixel") {
                pixel = parsePixel(arg, value());
                pixelGiven = true;
            } else if (arg == "--terminator") {
                const std::string_view text = value();
                if (text != "on" && text != "off")
                    throw UsageError("--terminator expects on or off, got '" + std::string(text) +
                                     "'");
                terminator = text == "on";
            } else if (arg == "--truncate") {
                settings.truncate = true;
            } else if (arg == "--mistake") {
                mistake = parseMistake(arg, value());
            } else if (arg == "--jpeg-quality") {
                jpegQuality = parseCount(arg, value(), 1);
                if (jpegQuality > 100)
                    throw UsageError("--jpeg-quality must be 1 to 100, got " +
                                     std::to_string(jpegQuality));
            } else if (arg.starts_with("-")) {
                throw UsageError("unknown option " + std::string(arg));
            } else if (scenePath.empty()) {
                scenePath = arg;
            } else {
                throw UsageError("more than one scene given: " + scenePath + ", " +
                                 std::string(arg));
            }
        }
        if (scenePath.empty()) throw UsageError("no scene file given");
        if (outputPath.empty() && !pixelGiven)
            throw UsageError("no output given (-o OUT.png, or --pixel X,Y)");
        if (mistake != Mistake::None && settings.spp != 1)
            throw UsageError("--mistake renders one sample per pixel, not --spp " +
                             std::to_string(settings.spp));
        if (pixelGiven && (pixel.x >= settings.width || pixel.y >= settings.height))
            throw UsageError("--pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) +
                             " lies outside the " + std::to_string(settings.width) + "x" +
                             std::to_string(settings.height) + " image");
        if (!outputPath.empty() && mistake != Mistake::None) {
            const std::optional<OutputFormat> format = outputFormatOf(outputPath);
            if (!format || isStandardOutput(outputPath))
                throw UsageError("-o " + outputPath +
                                 ": with --mistake, the output must be a file name ending in "
                                 ".png, .jpg, .jpeg, .ppm, .pfm or .exr");
            floatOutput = holdsFloats(*format);
        } else if (!outputPath.empty()) {
            const std::optional<ImageFormat> format = imageFormatOf(outputPath);
            if (!format)
                throw UsageError("-o " + outputPath +
                                 ": the output must be a file name ending in " +
                                 kKnownImageExtensions);
            floatOutput = *format != ImageFormat::Png;
            if (floatOutput && settings.truncate)
                throw UsageError("--truncate applies to PNG output only, not to " + outputPath);
        }
    } catch (const UsageError& error) {
        std::fprintf(stderr, "reference_render: %s (see --help)\n", error.what());
        return 2;
    }

    try {
        // An OBJ model is built as Raytracer builds it for the same view (docs/models.md).
        ModelSceneSetup modelSetup;
        modelSetup.fovDegrees = settings.fovDegrees;
        modelSetup.aspect = double(settings.width) / double(settings.height);
        modelSetup.camera = {settings.cameraPosition, settings.cameraTarget, settings.cameraUp};
        modelSetup.cameraGiven = cameraGiven;
        const Scene scene = loadScene(scenePath, modelSetup);
        settings.terminatorFix = terminator.value_or(scene.model.has_value());
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "%s\n", warning.c_str());
        if (!outputPath.empty()) {
            const auto start = std::chrono::steady_clock::now();
            std::chrono::duration<double> seconds{};
            if (mistake != Mistake::None) {
                Image8 bytes;
                const ImageF image = renderWithMistake(scene, settings, mistake, threads, &bytes);
                seconds = std::chrono::steady_clock::now() - start;
                if (floatOutput)
                    writeFloatImage(outputPath, image);
                else
                    writeImage8(outputPath, bytes, jpegQuality);
            } else if (floatOutput) {
                const ImageF image = renderReferenceFloat(scene, settings, threads);
                seconds = std::chrono::steady_clock::now() - start;
                writeFloatImage(outputPath, image);
            } else {
                const Image8 image = renderReference(scene, settings, threads);
                seconds = std::chrono::steady_clock::now() - start;
                writePng(outputPath, image);
            }
            std::fprintf(stderr, "reference_render: %s %dx%d depth %d spp %d in %.2f s\n",
                         scenePath.c_str(), settings.width, settings.height, settings.depth,
                         settings.spp, seconds.count());
        }
        if (pixelGiven) {
            const ReferenceStory story = referencePixelStory(scene, settings, pixel.x, pixel.y);
            std::fputs(
                referenceStoryJson(story, scene, settings, scenePath, pixel.x, pixel.y).c_str(),
                stdout);
        }
    } catch (const SceneError& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "reference_render: error: %s\n", error.what());
        return 1;
    }
    return 0;
}
