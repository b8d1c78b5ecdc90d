// image_diff A.png B.png [--tolerance T] [--min-match PERCENT] [--diff OUT.png]
// Exit status: 0 when enough pixels match, 1 when not, 2 on any error.
#include "image_compare.h"
#include "tool_arguments.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

const char* const usage =
    "usage: image_diff A.png B.png [--tolerance T] [--min-match PERCENT] [--diff OUT.png]\n"
    "Compares two PNGs pixel by pixel (RGB). A pixel matches when every channel\n"
    "differs by at most T levels (default 2). Exits 0 when at least PERCENT of the\n"
    "pixels match (default 99.5), 1 when fewer do, 2 on error. --diff writes a grey\n"
    "copy of A with the pixels over the tolerance in red.\n";

using tool_arguments::parseNumber;

} // namespace

int main(int argc, char** argv) {
    try {
        std::string paths[2], diffPath;
        int pathCount = 0;
        int tolerance = 2;
        double minMatchPercent = 99.5;
        for (int k = 1; k < argc; ++k) {
            const std::string_view arg = argv[k];
            auto value = [&]() -> std::string_view {
                if (k + 1 >= argc) throw std::invalid_argument(std::string(arg) + " needs a value");
                return argv[++k];
            };
            if (arg == "--help" || arg == "-h") {
                std::fputs(usage, stdout);
                return 0;
            } else if (arg == "--tolerance") {
                tolerance = parseNumber<int>(arg, value());
                if (tolerance < 0 || tolerance > 255)
                    throw std::invalid_argument("--tolerance must be in 0..255");
            } else if (arg == "--min-match") {
                minMatchPercent = parseNumber<double>(arg, value());
                if (!(minMatchPercent >= 0 && minMatchPercent <= 100))
                    throw std::invalid_argument("--min-match must be a percentage in 0..100");
            } else if (arg == "--diff") {
                diffPath = value();
            } else if (arg.starts_with("-")) {
                throw std::invalid_argument("unknown option " + std::string(arg));
            } else if (pathCount < 2) {
                paths[pathCount++] = arg;
            } else {
                throw std::invalid_argument("more than two images given");
            }
        }
        if (pathCount != 2) throw std::invalid_argument("two images are needed (see --help)");

        const Image8 a = readPng(paths[0]);
        const Image8 b = readPng(paths[1]);
        const ImageComparison comparison = compareImages(a, b, tolerance);
        std::printf("%s\n", describe(comparison).c_str());
        if (!diffPath.empty()) writePng(diffPath, diffImage(a, b, tolerance));
        // Compared in pixels, so that 99.5% of 19200 is not lost to rounding.
        const double needed = std::ceil(minMatchPercent / 100.0 * double(comparison.pixels) - 1e-9);
        return double(comparison.pixelsWithinTolerance) >= needed ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "image_diff: error: %s\n", error.what());
        return 2;
    }
}
