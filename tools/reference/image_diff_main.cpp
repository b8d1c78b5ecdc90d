// image_diff A B [--tolerance T] [--float-tolerance E] [--min-match PERCENT] [--diff OUT.png]
// A and B are PNG, PFM or OpenEXR files. Exit status: 0 when enough pixels match, 1 when
// not, 2 on any error.
#include "compare/float_compare.h"
#include "compare/image_compare.h"
#include "compare/ssim.h"
#include "tool_arguments.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

const char* const usage =
    "usage: image_diff A B [--tolerance T] [--float-tolerance E] [--min-match PERCENT]\n"
    "                  [--diff OUT.png]\n"
    "Compares two images pixel by pixel (RGB). Each is a PNG, or a PFM or OpenEXR float\n"
    "image (Raytracer -o out.pfm|out.exr: the averages before the 8-bit rounding); the\n"
    "format is read from the file's first bytes. A float image is compared with a PNG\n"
    "after the kernel's rounding, floor(c*255+0.5). A pixel matches when every channel\n"
    "differs by at most T levels (default 2). When both are float images it also reports\n"
    "the float errors (max absolute, RMSE), and a pixel matches when every channel differs\n"
    "by at most E (default 1e-4). SSIM (Wang et al. 2004: 11x11 Gaussian window, sigma 1.5,\n"
    "K1 0.01, K2 0.03; per RGB channel, averaged) is printed on the 8-bit values (L = 255)\n"
    "and, for two float images, on the floats (L = 1). Exits 0 when at least PERCENT of the\n"
    "pixels match (default 99.5; judged on the floats when both are float images), 1 when\n"
    "fewer do, 2 on error. --diff writes a grey copy of A with the pixels over T in red.\n";

using tool_arguments::parseNumber;

// An input as 8-bit pixels, and its floats when the file holds floats.
struct InputImage {
    Image8 bytes;
    std::optional<ImageF> floats;
};

std::optional<ImageFormat> formatFromMagic(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    char magic[8] = {};
    file.read(magic, sizeof magic);
    const std::streamsize got = file.gcount();
    if (got >= 8 && std::memcmp(magic, "\x89PNG\r\n\x1a\n", 8) == 0) return ImageFormat::Png;
    if (got >= 4 && std::memcmp(magic, "\x76\x2f\x31\x01", 4) == 0) return ImageFormat::Exr;
    if (got >= 3 && magic[0] == 'P' && (magic[1] == 'F' || magic[1] == 'f'))
        return ImageFormat::Pfm;
    return std::nullopt;
}

InputImage readInput(const std::string& path) {
    // The bytes decide; a file whose bytes match no format is read as its name says, so
    // that the error is that format's.
    std::optional<ImageFormat> format = formatFromMagic(path);
    if (!format) format = imageFormatOf(path);
    if (!format)
        throw std::runtime_error(path + ": not a PNG, PFM or OpenEXR image (neither its first "
                                        "bytes nor its name say which)");
    InputImage input;
    if (format == ImageFormat::Png) {
        input.bytes = readPng(path);
    } else {
        input.floats = format == ImageFormat::Pfm ? readPfm(path) : readExr(path);
        input.bytes = quantizeImage(*input.floats);
    }
    return input;
}

// "SSIM 0.99871 (8-bit, L = 255)", or why there is none.
std::string ssimLine(const char* what, const ImageF& a, const ImageF& b, double dataRange) {
    char text[128];
    if (a.width < kSsimWindow || a.height < kSsimWindow) {
        std::snprintf(text, sizeof text, "%s n/a (the images are under %dx%d pixels)", what,
                      kSsimWindow, kSsimWindow);
    } else {
        std::snprintf(text, sizeof text, "%s %.6f (L = %g, RGB channels averaged)", what,
                      structuralSimilarity(a, b, dataRange), dataRange);
    }
    return text;
}

// At least minMatchPercent of pixels, compared in pixels, so that 99.5% of 19200 is not
// lost to rounding.
bool enoughMatch(long within, long pixels, double minMatchPercent) {
    return double(within) >= std::ceil(minMatchPercent / 100.0 * double(pixels) - 1e-9);
}

} // namespace

int main(int argc, char** argv) {
    try {
        std::string paths[2], diffPath;
        int pathCount = 0;
        int tolerance = 2;
        double floatTolerance = 1e-4;
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
            } else if (arg == "--float-tolerance") {
                floatTolerance = parseNumber<double>(arg, value());
                if (floatTolerance < 0)
                    throw std::invalid_argument("--float-tolerance must not be negative");
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

        const InputImage a = readInput(paths[0]);
        const InputImage b = readInput(paths[1]);
        const ImageComparison comparison = compareImages(a.bytes, b.bytes, tolerance);
        std::printf("%s\n", describe(comparison).c_str());
        std::printf("%s\n",
                    ssimLine("SSIM 8-bit", imageFromBytes(a.bytes), imageFromBytes(b.bytes), 255.0)
                        .c_str());
        bool passed =
            enoughMatch(comparison.pixelsWithinTolerance, comparison.pixels, minMatchPercent);
        if (a.floats && b.floats) {
            const FloatComparison floats = compareFloatImages(*a.floats, *b.floats, floatTolerance);
            std::printf("%s\n", describe(floats).c_str());
            std::printf("%s\n", ssimLine("SSIM float", *a.floats, *b.floats, 1.0).c_str());
            passed = enoughMatch(floats.pixelsWithinTolerance, floats.pixels, minMatchPercent);
        }
        if (!diffPath.empty()) writePng(diffPath, diffImage(a.bytes, b.bytes, tolerance));
        return passed ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "image_diff: error: %s\n", error.what());
        return 2;
    }
}
