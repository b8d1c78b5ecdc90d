// Float images and their files (host/base/float_image.h): PFM bytes as the format defines
// them, read back bit for bit in both byte orders and from grey files; EXR round trips; the
// kernel's 8-bit rounding; damaged files answered with an error that says what is wrong.
#include "base/float_image.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>

namespace {

std::filesystem::path outputDir() {
    std::filesystem::path dir = std::filesystem::path(TEST_OUTPUT_DIR) / "float_image_test";
    std::filesystem::create_directories(dir);
    return dir;
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

std::string readBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), {});
}

// Random values with awkward bits: subnormals, values just off 8-bit ties, 0, 1, > 1.
ImageF randomImage(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    ImageF image{width, height, {}};
    for (int k = 0; k < width * height * 3; ++k)
        image.rgb.push_back(unit(random));
    image.rgb[0] = 0.0f;
    image.rgb[1] = 1.0f;
    image.rgb[2] = std::nextafter(0.5f / 255.0f, 1.0f);
    if (image.rgb.size() > 5) {
        image.rgb[3] = 1e-40f; // subnormal
        image.rgb[4] = 3.5f;   // a light brighter than 1 may be stored (never by the kernel)
    }
    return image;
}

std::string littleEndian(float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    std::string out;
    for (int b = 0; b < 4; ++b)
        out += char(bits >> (8 * b));
    return out;
}

std::string bigEndian(float value) {
    std::string out = littleEndian(value);
    return std::string(out.rbegin(), out.rend());
}

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "(no error)";
}

} // namespace

TEST(FloatImage, FormatsComeFromTheExtensionInAnyCase) {
    EXPECT_EQ(imageFormatOf("a.png"), ImageFormat::Png);
    EXPECT_EQ(imageFormatOf("dir.x/a.PFM"), ImageFormat::Pfm);
    EXPECT_EQ(imageFormatOf("a.Exr"), ImageFormat::Exr);
    EXPECT_EQ(imageFormatOf("a.jpg"), std::nullopt);
    EXPECT_EQ(imageFormatOf("png"), std::nullopt);
    EXPECT_EQ(imageFormatOf("a.png.tmp"), std::nullopt);
}

// The bytes the PFM definition asks for, written out here by hand: header, then floats
// little-endian (scale -1), the bottom row first.
TEST(FloatImage, PfmHoldsTheHeaderAndRowsBottomToTop) {
    const ImageF image{
        2, 2, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f, 1.0f, 0.0f, 0.25f}};
    const auto path = outputDir() / "two_by_two.pfm";
    writePfm(path, image);
    std::string expected = "PF\n2 2\n-1.0\n";
    for (int k : {6, 7, 8, 9, 10, 11, 0, 1, 2, 3, 4, 5}) // row 1 (bottom), then row 0
        expected += littleEndian(image.rgb[std::size_t(k)]);
    EXPECT_EQ(readBytes(path), expected);
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
}

TEST(FloatImage, PfmAndExrReadBackBitForBit) {
    const ImageF image = randomImage(37, 23, 7);
    for (const char* name : {"random.pfm", "random.exr"}) {
        const auto path = outputDir() / name;
        if (imageFormatOf(path) == ImageFormat::Pfm)
            writePfm(path, image);
        else
            writeExr(path, image);
        const ImageF back = imageFormatOf(path) == ImageFormat::Pfm ? readPfm(path) : readExr(path);
        ASSERT_EQ(back.width, 37) << name;
        ASSERT_EQ(back.height, 23) << name;
        ASSERT_EQ(back.rgb.size(), image.rgb.size()) << name;
        EXPECT_EQ(std::memcmp(back.rgb.data(), image.rgb.data(), image.rgb.size() * 4), 0) << name;
    }
    // A tiny EXR is stored uncompressed, a larger one compressed: both read back.
    const ImageF small = randomImage(3, 2, 8);
    writeExr(outputDir() / "small.exr", small);
    EXPECT_EQ(readExr(outputDir() / "small.exr").rgb, small.rgb);
}

TEST(FloatImage, PfmReadsBigEndianAndGreyFiles) {
    const auto big = outputDir() / "big_endian.pfm";
    std::string bytes = "PF\n1 2\n1.0\n"; // positive scale: big-endian
    for (float v : {0.5f, 0.25f, 0.125f, 1.0f, 0.75f, 0.0f})
        bytes += bigEndian(v);
    writeBytes(big, bytes);
    const ImageF image = readPfm(big);
    EXPECT_EQ(image.rgb, (std::vector<float>{1.0f, 0.75f, 0.0f, 0.5f, 0.25f, 0.125f}));

    const auto grey = outputDir() / "grey.pfm";
    writeBytes(grey, "Pf 2 1 -1\n" + littleEndian(0.2f) + littleEndian(0.9f));
    EXPECT_EQ(readPfm(grey).rgb, (std::vector<float>{0.2f, 0.2f, 0.2f, 0.9f, 0.9f, 0.9f}));
}

// floor(c * 255 + 0.5) in float: values either side of the ties, a tie (127.5) rounding up.
TEST(FloatImage, QuantizeRoundsAsTheKernelDoes) {
    const ImageF image{2,
                       2,
                       {0.0f, 0.499f / 255.0f, 0.501f / 255.0f, 1.0f, 0.2f, 0.5f, 127.5f / 255.0f,
                        254.49f / 255.0f, 254.51f / 255.0f, -1.0f, 2.0f,
                        std::nextafter(1.0f, 0.0f)}};
    const Image8 bytes = quantizeImage(image);
    const std::vector<std::uint8_t> expected = {0,   0,   1,   255, // (0,0), alpha 255
                                                255, 51,  128, 255, // 0.2*255 = 51, 127.5 up
                                                128, 254, 255, 255, 0, 255, 255, 255}; // clamped
    EXPECT_EQ(bytes.rgba, expected);
    EXPECT_EQ(bytes.width, 2);
    EXPECT_EQ(imageFromBytes(bytes).rgb[4], 51.0f);
}

TEST(FloatImage, DamagedPfmFilesSayWhatIsWrong) {
    const auto path = outputDir() / "damaged.pfm";
    auto readText = [&](const std::string& bytes) {
        writeBytes(path, bytes);
        return errorOf([&] { readPfm(path); });
    };
    const std::string p = path.string() + ": ";
    EXPECT_EQ(readText(""),
              p + "not a PFM file (expected 'PF' or 'Pf' and a line break at the start)");
    EXPECT_EQ(readText("P6\n1 1\n255\n"),
              p + "not a PFM file (expected 'PF' or 'Pf' and a line break at the start)");
    EXPECT_EQ(readText("PF\n"), p + "PFM header ends before its width");
    EXPECT_EQ(readText("PF\n2 x\n-1\n"), p + "PFM header: expected the height, got 'x'");
    EXPECT_EQ(readText("PF\n2\xff 1\n-1\n"), p + "PFM header: expected the width, got '2\\xff'");
    EXPECT_EQ(readText("PF\n0 1\n-1\n"), p + "PFM size 0x1 is not 1..65536 a side");
    EXPECT_EQ(readText("PF\n1 1\n0\n"), p + "PFM scale must be a non-zero number");
    EXPECT_EQ(readText("PF\n1 1\n-1"), p + "PFM header: expected a line break after the scale");
    EXPECT_EQ(readText("PF\n2 1\n-1\n" + littleEndian(0.5f)),
              p + "PFM pixels truncated: 2x1x3 floats need 24 bytes, the file holds 4");
    EXPECT_EQ(
        readText("PF\n1 1\n-1\n" + littleEndian(0.5f) + littleEndian(NAN) + littleEndian(0.5f)),
        p + "pixel (0,0) holds a non-finite value");
    EXPECT_EQ(errorOf([&] { readPfm(outputDir() / "missing.pfm"); }),
              (outputDir() / "missing.pfm").string() + ": cannot open: No such file or directory");
}

TEST(FloatImage, DamagedExrFilesSayWhatIsWrong) {
    const auto good = outputDir() / "good.exr";
    writeExr(good, randomImage(40, 30, 9));
    const std::string bytes = readBytes(good);
    const auto path = outputDir() / "damaged.exr";
    writeBytes(path, "not an exr at all");
    EXPECT_EQ(errorOf([&] { readExr(path); }),
              path.string() + ": not an OpenEXR file (expected the magic number 76 2f 31 01)");
    // Every truncation, at many lengths, is an error naming the file; none reads back.
    for (std::size_t length = 4; length < bytes.size(); length += 1 + length / 8) {
        writeBytes(path, bytes.substr(0, length));
        const std::string error = errorOf([&] { readExr(path); });
        EXPECT_EQ(error.rfind(path.string() + ": not a readable OpenEXR image: ", 0), 0u)
            << "length " << length << ": " << error;
    }
}

TEST(FloatImage, EmptyImagesAreNotWritten) {
    const auto path = outputDir() / "empty.pfm";
    EXPECT_EQ(errorOf([&] { writePfm(path, ImageF{}); }),
              path.string() + ": cannot write an empty image (0x0)");
    EXPECT_EQ(errorOf([&] {
                  writeFloatImage(outputDir() / "x.png", ImageF{1, 1, {0, 0, 0}});
              }),
              (outputDir() / "x.png").string() +
                  ": not a float image file name (expected .pfm or .exr)");
}
