// What the command line's output pieces say and write, without Vulkan: the progress lines
// word for word, -o's formats by name, PPM bytes by hand, the no-display fallback's next
// free name, and drivers' version numbers.
#include "base/output_format.h"
#include "base/progress.h"
#include "gpu/device_list.h"

#include <gtest/gtest.h>

#include <fstream>

namespace {

TEST(ProgressText, PlainAndTerminalLinesWordForWord) {
    // 42% done in 3.1 s: the remaining 58% at the same pace takes 3.1 * 58 / 42 = 4.28 s.
    EXPECT_EQ(plainProgressLine(0.42, 3.1), "progress: 42% 3.1 s elapsed, about 4.3 s left");
    EXPECT_EQ(terminalProgressText(1500, 1100, 0.375, 3.0),
              "Rendering 1500x1100: 37% (3.0 s elapsed, about 5.0 s left)");
    EXPECT_EQ(plainProgressLine(0.999, 10.0), "progress: 99% 10.0 s elapsed, about 0.0 s left");
    EXPECT_DOUBLE_EQ(secondsLeft(0.5, 2.0), 2.0);
    EXPECT_DOUBLE_EQ(secondsLeft(0.0, 2.0), 0.0); // nothing done: no estimate
    EXPECT_DOUBLE_EQ(secondsLeft(1.0, 2.0), 0.0);
}

TEST(OutputFormat, ByExtensionInAnyCase) {
    EXPECT_EQ(outputFormatOf("a.png"), OutputFormat::Png);
    EXPECT_EQ(outputFormatOf("a.JPG"), OutputFormat::Jpeg);
    EXPECT_EQ(outputFormatOf("dir.x/a.jpeg"), OutputFormat::Jpeg);
    EXPECT_EQ(outputFormatOf("a.Ppm"), OutputFormat::Ppm);
    EXPECT_EQ(outputFormatOf("a.pfm"), OutputFormat::Pfm);
    EXPECT_EQ(outputFormatOf("a.exr"), OutputFormat::Exr);
    EXPECT_EQ(outputFormatOf("-"), OutputFormat::Png);
    EXPECT_EQ(outputFormatOf("a.bmp"), std::nullopt);
    EXPECT_EQ(outputFormatOf("jpg"), std::nullopt);
    EXPECT_EQ(outputFormatOf("a.jpg.tmp"), std::nullopt);
    EXPECT_EQ(outputFormatOf("./-"), std::nullopt); // a file named "-" is no stdout
    EXPECT_TRUE(holdsFloats(OutputFormat::Exr));
    EXPECT_FALSE(holdsFloats(OutputFormat::Jpeg));
}

TEST(OutputFormat, PpmIsP6ThenRgbRows) {
    Image8 image;
    image.width = 2;
    image.height = 1;
    image.rgba = {1, 2, 3, 255, 250, 251, 252, 255};
    const std::vector<std::uint8_t> bytes = encodePpm("x.ppm", image);
    const std::string expected = std::string("P6\n2 1\n255\n") + "\x01\x02\x03\xFA\xFB\xFC";
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), expected);
}

TEST(OutputFormat, FirstUnusedNameCountsUpFromOne) {
    const std::filesystem::path dir = std::filesystem::path(TEST_OUTPUT_DIR) / "unused-name";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    EXPECT_EQ(firstUnusedName(dir / "test1.png"), dir / "test1.png");
    std::ofstream(dir / "test1.png") << "x";
    EXPECT_EQ(firstUnusedName(dir / "test1.png"), dir / "test1-1.png");
    std::ofstream(dir / "test1-1.png") << "x";
    std::ofstream(dir / "test1-3.png") << "x";
    EXPECT_EQ(firstUnusedName(dir / "test1.png"), dir / "test1-2.png");
}

TEST(DeviceList, DriverVersionsAsTheirVendorsPackThem) {
    EXPECT_EQ(driverVersionText(0x10005, VK_MAKE_API_VERSION(0, 23, 1, 7)), "23.1.7");
    // NVIDIA: 10 bits major, 8 minor, 8 secondary, 6 tertiary (535.104.5.0).
    EXPECT_EQ(driverVersionText(0x10DE, (535u << 22) | (104u << 14) | (5u << 6)), "535.104.5.0");
}

} // namespace
