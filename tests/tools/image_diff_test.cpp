// image_diff on float inputs (PFM, EXR) and mixed with PNG: the float figures against values
// worked out here from the pixels the test made; the 8-bit report for PNG/PNG in its exact
// wording; damaged PFM and EXR files (truncated at many lengths, random bytes with and
// without the right magic) answered with "image_diff: error: FILE: ..." and status 2, never
// a crash.
#include "test_support.h"

#include "base/float_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <regex>

namespace {

constexpr int kWidth = 20, kHeight = 15, kPixels = kWidth * kHeight;

ImageF gradient() {
    ImageF image{kWidth, kHeight, {}};
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            image.rgb.insert(image.rgb.end(), {float(x) / kWidth, float(y) / kHeight, 0.37f});
    return image;
}

float& channel(ImageF& image, int x, int y, int c) {
    return image.rgb[(std::size_t(y) * kWidth + std::size_t(x)) * 3 + std::size_t(c)];
}

// The difference b - a of one channel, in double as image_diff takes it.
double difference(const ImageF& a, const ImageF& b, int x, int y, int c) {
    const std::size_t k = (std::size_t(y) * kWidth + std::size_t(x)) * 3 + std::size_t(c);
    return double(b.rgb[k]) - double(a.rgb[k]);
}

// The kernel's rounding written out again here: floor(c * 255 + 0.5) in float.
Image8 roundedByHand(const ImageF& image) {
    Image8 out{image.width, image.height, {}};
    for (std::size_t p = 0; p < image.rgb.size() / 3; ++p) {
        for (std::size_t c = 0; c < 3; ++c)
            out.rgba.push_back(std::uint8_t(std::floor(image.rgb[p * 3 + c] * 255.0f + 0.5f)));
        out.rgba.push_back(255);
    }
    return out;
}

ProcessResult imageDiff(std::vector<std::string> args) {
    return runProgram(IMAGE_DIFF_BINARY, args, 60);
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

} // namespace

TEST(ImageDiff, FloatInputsReportMaxErrorRmseAndShareWithinTolerance) {
    const std::filesystem::path dir = freshOutputDir("image_diff/float");
    const ImageF a = gradient();
    ImageF b = a;
    channel(b, 3, 2, 1) += 0.01f;    // over any float tolerance below 0.01
    channel(b, 5, 1, 0) += 0.00005f; // within 1e-4
    writePfm(dir / "a.pfm", a);
    writeExr(dir / "b.exr", b);
    const double big = difference(a, b, 3, 2, 1), small = difference(a, b, 5, 1, 0);
    const double rmse = std::sqrt((big * big + small * small) / (3.0 * kPixels));

    const ProcessResult run = imageDiff({(dir / "a.pfm").string(), (dir / "b.exr").string(),
                                         "--float-tolerance", "1e-4", "--min-match", "100"});
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err; // one pixel of 300 over 1e-4
    std::smatch match;
    const std::regex floatLine(
        R"(float: ([0-9.]+)% of ([0-9]+) pixels within ([0-9.e-]+), max abs error ([0-9.e-]+) at \(([0-9]+),([0-9]+)\), RMSE ([0-9.e-]+)\n)");
    ASSERT_TRUE(std::regex_search(run.out, match, floatLine)) << run.out;
    EXPECT_EQ(match[1].str(), "99.66"); // 299 of 300, rounded down
    EXPECT_EQ(match[2].str(), std::to_string(kPixels));
    EXPECT_EQ(std::stod(match[3].str()), 1e-4);
    EXPECT_NEAR(std::stod(match[4].str()), big, 1e-3 * big); // printed to 4 digits
    EXPECT_EQ(match[5].str() + "," + match[6].str(), "3,2");
    EXPECT_NEAR(std::stod(match[7].str()), rmse, 1e-3 * rmse);
    EXPECT_NE(run.out.find("\nSSIM float "), std::string::npos) << run.out;

    // The floats decide the status: within 0.02 everywhere, though 0.01 is 2.55 levels.
    EXPECT_EQ(imageDiff({(dir / "a.pfm").string(), (dir / "b.exr").string(), "--tolerance", "0",
                         "--float-tolerance", "0.02", "--min-match", "100"})
                  .exitCode,
              0);
    EXPECT_EQ(imageDiff({(dir / "a.pfm").string(), (dir / "b.exr").string(), "--min-match", "99"})
                  .exitCode,
              0);
    const ProcessResult same = imageDiff({(dir / "a.pfm").string(), (dir / "a.pfm").string()});
    EXPECT_EQ(same.exitCode, 0);
    EXPECT_NE(same.out.find("float: 100% of 300 pixels within 0.0001, max abs error 0 at (0,0), "
                            "RMSE 0\nSSIM float 1.000000 (L = 1, RGB channels averaged)\n"),
              std::string::npos)
        << same.out;
}

TEST(ImageDiff, FloatAgainstPngComparesTheKernelsRounding) {
    const std::filesystem::path dir = freshOutputDir("image_diff/mixed");
    const ImageF a = gradient();
    Image8 png = roundedByHand(a);
    writePfm(dir / "a.pfm", a);
    writePng(dir / "a.png", png);
    const ProcessResult same = imageDiff({(dir / "a.pfm").string(), (dir / "a.png").string(),
                                          "--tolerance", "0", "--min-match", "100"});
    EXPECT_EQ(same.exitCode, 0) << same.out << same.err;
    EXPECT_EQ(same.out, "100% of 300 pixels within 0/255, max diff 0/255 at (0,0), RMSE 0.00\n"
                        "SSIM 8-bit 1.000000 (L = 255, RGB channels averaged)\n");
    png.rgba[(2 * kWidth + 7) * 4 + 2] += 1;
    writePng(dir / "a.png", png);
    const ProcessResult off = imageDiff({(dir / "a.png").string(), (dir / "a.pfm").string()});
    EXPECT_EQ(off.exitCode, 0);
    EXPECT_NE(off.out.find("100% of 300 pixels within 2/255, max diff 1/255 at (7,2), RMSE 0.03\n"),
              std::string::npos)
        << off.out; // sqrt(1 / 900) = 0.033
    EXPECT_EQ(off.out.find("float:"), std::string::npos) << "a PNG has no float figures";
}

// The first line is the report the scripts and tests have always read.
TEST(ImageDiff, PngReportKeepsItsWording) {
    const std::filesystem::path dir = freshOutputDir("image_diff/png");
    Image8 a = roundedByHand(gradient()), b = a;
    b.rgba[(4 * kWidth + 9) * 4] += 5;
    writePng(dir / "a.png", a);
    writePng(dir / "b.png", b);
    const ProcessResult run = imageDiff({(dir / "a.png").string(), (dir / "b.png").string()});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.out.substr(0, run.out.find('\n') + 1),
              "99.66% of 300 pixels within 2/255, max diff 5/255 at (9,4), RMSE 0.17\n");
}

TEST(ImageDiff, DamagedFloatFilesAreErrorsNotCrashes) {
    const std::filesystem::path dir = freshOutputDir("image_diff/damaged");
    const ImageF image = gradient();
    writePfm(dir / "good.pfm", image);
    writeExr(dir / "good.exr", image);
    std::mt19937 random(11);
    for (const char* extension : {".pfm", ".exr"}) {
        const std::string good = readWholeFile(dir / (std::string("good") + extension));
        std::vector<std::string> damaged;
        for (std::size_t length = 0; length < good.size(); length += 1 + length / 6)
            damaged.push_back(good.substr(0, length));
        for (int k = 0; k < 8; ++k) {
            std::string garbage(std::size_t(16 + 97 * k), '\0');
            for (char& c : garbage)
                c = char(random());
            damaged.push_back(garbage);
            damaged.push_back(good.substr(0, 4) + garbage); // the right magic, then noise
        }
        for (std::size_t k = 0; k < damaged.size(); ++k) {
            const std::filesystem::path path = dir / ("damaged" + std::to_string(k) + extension);
            writeBytes(path, damaged[k]);
            const ProcessResult run =
                imageDiff({path.string(), (dir / (std::string("good") + extension)).string()});
            EXPECT_EQ(run.exitCode, 2) << path << ": " << run.err;
            EXPECT_EQ(run.err.rfind("image_diff: error: " + path.string() + ": ", 0), 0u)
                << run.err;
            EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
        }
    }
    // Neither the name nor the bytes say what it is.
    writeBytes(dir / "mystery.dat", "hello");
    const ProcessResult mystery =
        imageDiff({(dir / "mystery.dat").string(), (dir / "good.pfm").string()});
    EXPECT_EQ(mystery.exitCode, 2);
    EXPECT_EQ(mystery.err, "image_diff: error: " + (dir / "mystery.dat").string() +
                               ": not a PNG, PFM or OpenEXR image (neither its first bytes nor "
                               "its name say which)\n");
}
