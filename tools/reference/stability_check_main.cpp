// stability_check SCENE [options] IMAGE.png...: how many pixels of each image are wrong
// against the CPU reference's range (reference_range.h), as CSV on stdout. Used by
// tools/stability and tools/speed_accuracy; the stability test calls the library.
#include "model/scene_file.h"
#include "reference_range.h"
#include "scene/scene_loader.h"
#include "tool_arguments.h"

#include <charconv>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

const char* const usage =
    "usage: stability_check SCENE [--width W] [--height H] [--fov DEG] [--depth D]\n"
    "                       [--tolerance T] [--wrong-images DIR] IMAGE.png...\n"
    "Compares each IMAGE (rendered from SCENE with the same settings, one sample per pixel)\n"
    "with the double-precision CPU reference. A pixel is wrong when some channel lies more\n"
    "than T levels (default 2) outside the range of the reference's values over the pixel\n"
    "centre and eight rays moved a tiny sub-pixel distance (knife edges are excused).\n"
    "Prints CSV: image,pixels,differing,wrong,failure_rate,worst_x,worst_y,worst_excess.\n"
    "  --wrong-images DIR   also write DIR/NAME-wrong.png: wrong pixels red, excused yellow\n";

using tool_arguments::parseCount;
using tool_arguments::parseFov;
using tool_arguments::UsageError;

} // namespace

int main(int argc, char** argv) {
    ReferenceSettings settings;
    settings.width = 160;
    settings.height = 120;
    int tolerance = 2;
    std::string scenePath;
    std::filesystem::path wrongImages;
    std::vector<std::string> images;
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
            } else if (arg == "--width") {
                settings.width = parseCount(arg, value(), 1);
            } else if (arg == "--height") {
                settings.height = parseCount(arg, value(), 1);
            } else if (arg == "--fov") {
                settings.fovDegrees = parseFov(arg, value());
            } else if (arg == "--depth") {
                settings.depth = parseCount(arg, value(), 0);
            } else if (arg == "--tolerance") {
                tolerance = parseCount(arg, value(), 0);
            } else if (arg == "--wrong-images") {
                wrongImages = std::string(value());
            } else if (arg.starts_with("-")) {
                throw UsageError("unknown option " + std::string(arg));
            } else if (scenePath.empty()) {
                scenePath = arg;
            } else {
                images.emplace_back(arg);
            }
        }
        if (scenePath.empty() || images.empty())
            throw UsageError("expected a scene and at least one image");
        if (settings.width < 1 || settings.height < 1 || settings.depth < 0 || tolerance < 0 ||
            !(settings.fovDegrees > 0 && settings.fovDegrees < 180))
            throw UsageError("expected a positive size, a depth and tolerance of at least 0, "
                             "and a field of view strictly between 0 and 180 degrees");
    } catch (const UsageError& error) {
        std::fprintf(stderr, "stability_check: %s (see --help)\n", error.what());
        return 2;
    }
    try {
        const Scene scene = loadScene(scenePath);
        ReferenceRange range(scene, settings);
        std::printf("image,pixels,differing,wrong,failure_rate,worst_x,worst_y,worst_excess\n");
        for (const std::string& path : images) {
            const Image8 image = readPng(path);
            const StabilityCount count = countWrongPixels(image, range, tolerance);
            std::printf("%s,%ld,%ld,%ld,%.6g,%d,%d,%d\n", path.c_str(), count.pixels,
                        count.differing, count.wrong, count.failureRate, count.worstX, count.worstY,
                        count.worstExcess);
            if (!wrongImages.empty())
                writePng(wrongImages / (std::filesystem::path(path).stem().string() + "-wrong.png"),
                         wrongPixelImage(image, range, tolerance));
        }
    } catch (const SceneError& error) {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "stability_check: error: %s\n", error.what());
        return 1;
    }
    return 0;
}
