// The command line's daily use: -o's 8-bit formats (PNG, JPEG, PPM, a PNG on stdout),
// --list-devices, --quiet, the no-display fallback that never replaces an earlier render,
// and progress lines when stderr is not a terminal.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <sstream>

namespace {

const std::string kSeeHelp = "Run 'Raytracer --help' for the list of options.\n";

std::string minimalScene() {
    return "2\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -3\nrad: 1\ndif: 0.5 0.2 0.2\nspe: 0.3 0.3 0.3\n"
           "shi: 10\nlight\npos: 2 2 0\ncol: 1 1 1\n";
}

std::filesystem::path writeScene(const std::filesystem::path& dir, const std::string& text) {
    const std::filesystem::path path = dir / "input.scene";
    writeTextFile(path, text);
    return path;
}

// Renders the minimal scene at 64 x 48 to output with extra flags; fails the test on error.
void render(const std::filesystem::path& scene, const std::filesystem::path& output,
            const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {scene.string(), "-o", output.string(), "--width", "64",
                                     "--height",     "48", "--validate"};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult run = runRaytracer(args);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(std::filesystem::exists(output.string() + ".tmp")) << output;
}

double meanChannelDifference(const Image8& a, const Image8& b) {
    double sum = 0;
    std::size_t channels = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue; // alpha: 255 in both
        sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
        ++channels;
    }
    return sum / double(channels);
}

TEST(OutputFormats, PpmHoldsThePngsPixelsExactly) {
    const std::filesystem::path dir = freshOutputDir("cli-output/ppm");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    render(scene, dir / "out.png");
    render(scene, dir / "out.ppm");
    const std::string bytes = readWholeFile(dir / "out.ppm");
    const std::string header = "P6\n64 48\n255\n";
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    EXPECT_EQ(bytes.size(), header.size() + 64 * 48 * 3);
    const Image8 png = readPng(dir / "out.png"), ppm = readImage8(dir / "out.ppm");
    EXPECT_EQ(ppm.width, 64);
    EXPECT_EQ(ppm.height, 48);
    EXPECT_EQ(ppm.rgba, png.rgba);
}

// JPEG is lossy: at the default quality 90 the mean difference from the PNG stays within
// 1.5 levels of 255 per channel (measured 0.8 on this scene, and 5.0 at quality 20); quality 20
// makes a smaller file.
TEST(OutputFormats, JpegIsCloseToThePngAndQualitySetsItsSize) {
    const std::filesystem::path dir = freshOutputDir("cli-output/jpeg");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    render(scene, dir / "out.png");
    render(scene, dir / "default.jpg");
    render(scene, dir / "q90.jpeg", {"--quality", "90"});
    render(scene, dir / "q20.JPG", {"--quality=20"});
    const std::string bytes = readWholeFile(dir / "default.jpg");
    ASSERT_GE(bytes.size(), 3u);
    EXPECT_EQ(bytes.substr(0, 3), "\xFF\xD8\xFF"); // a JPEG's start-of-image marker
    EXPECT_EQ(readWholeFile(dir / "q90.jpeg"), bytes) << "the default quality is 90";
    const Image8 png = readPng(dir / "out.png");
    const Image8 jpeg = readImage8(dir / "default.jpg"), low = readImage8(dir / "q20.JPG");
    ASSERT_EQ(jpeg.width, 64);
    ASSERT_EQ(jpeg.height, 48);
    const double difference = meanChannelDifference(jpeg, png);
    const double lowDifference = meanChannelDifference(low, png);
    std::printf("JPEG mean channel difference from the PNG: quality 90 %.3f (%zu bytes), "
                "quality 20 %.3f (%zu bytes)\n",
                difference, bytes.size(), lowDifference, readWholeFile(dir / "q20.JPG").size());
    EXPECT_LE(difference, 1.5);
    EXPECT_GT(lowDifference, difference);
    EXPECT_LT(readWholeFile(dir / "q20.JPG").size(), bytes.size());
}

// The write is atomic as for PNG: a run that fails after the output was reserved leaves an
// earlier file as it was, and no .tmp.
TEST(OutputFormats, AFailedRunLeavesAnEarlierJpegOrPpm) {
    const std::filesystem::path dir = freshOutputDir("cli-output/atomic");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    for (const char* name : {"old.jpg", "old.ppm"}) {
        const std::filesystem::path output = dir / name;
        writeTextFile(output, "an earlier render");
        const ProcessResult run =
            runRaytracer({scene.string(), "-o", output.string(), "--device", "no-such-gpu"});
        EXPECT_EQ(run.exitCode, 1) << run.err;
        EXPECT_EQ(readWholeFile(output), "an earlier render");
        EXPECT_FALSE(std::filesystem::exists(output.string() + ".tmp"));
        render(scene, output); // and a good run replaces it
        EXPECT_EQ(readImage8(output).width, 64);
    }
}

// -o - : the PNG's bytes on stdout, the very bytes of -o x.png, and nothing else there.
TEST(OutputFormats, DashWritesThePngToStdout) {
    const std::filesystem::path dir = freshOutputDir("cli-output/stdout");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    render(scene, dir / "x.png");
    const ProcessResult run = runRaytracer(
        {scene.string(), "-o", "-", "--width", "64", "--height", "48", "--validate"}, 300, dir);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out, readWholeFile(dir / "x.png"));
    EXPECT_NE(run.err.find("Wrote the PNG to stdout\n"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "-"));
    EXPECT_FALSE(std::filesystem::exists(dir / "-.tmp"));
}

TEST(OutputFormats, UsageErrorsNameWhatIsWrong) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"x.scene", "-o", "out.bmp"},
         "error: -o out.bmp: the output must be a file name ending in .png, .jpg, .jpeg, .ppm, "
         ".pfm or .exr, or - for a PNG on stdout\n"},
        {{"x.scene", "-o", "x.png", "--quality", "50"},
         "error: --quality sets a JPEG's quality and needs -o FILE.jpg or FILE.jpeg, got -o "
         "x.png\n"},
        {{"x.scene", "--quality", "50"},
         "error: --quality sets a JPEG's quality and needs -o FILE.jpg or FILE.jpeg\n"},
        {{"x.scene", "-o", "-", "--quality", "50"},
         "error: --quality sets a JPEG's quality and needs -o FILE.jpg or FILE.jpeg, got -o -\n"},
        {{"x.scene", "-o", "x.jpg", "--quality", "0"},
         "error: --quality expects a whole number from 1 to 100, got '0'\n"},
        {{"x.scene", "-o", "x.jpg", "--quality", "101"},
         "error: --quality expects a whole number from 1 to 100, got '101'\n"},
        {{"x.scene", "-o", "-", "--pixel", "1,1"},
         "error: -o - writes the PNG to stdout and cannot be combined with --pixel or --bench, "
         "which print JSON there\n"},
        {{"x.scene", "--bench", "2", "-o", "-"},
         "error: -o - writes the PNG to stdout and cannot be combined with --pixel or --bench, "
         "which print JSON there\n"},
    };
    for (const auto& [args, message] : cases) {
        const ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_EQ(run.err, message + kSeeHelp);
        EXPECT_EQ(run.out, "");
    }
}

TEST(ListDevices, PrintsLavapipeWithItsTypeDriverAndLimits) {
    const ProcessResult run = runRaytracer({"--list-devices"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(run.out.rfind("[0] llvmpipe", 0), 0u) << run.out;
    for (const char* field :
         {"\n  type: cpu\n", "\n  driver: llvmpipe\n", "\n  driver info: Mesa ",
          "\n  driver version: ", "\n  vulkan: 1.", "\n  fp64 (shaderFloat64): yes\n",
          "\n  maxComputeWorkGroupInvocations: ", "\n  maxImageDimension2D: ",
          "\n  maxTexelBufferElements: ", "\n  maxStorageBufferRange: ",
          "\nChoose one with --device INDEX (the number in brackets) or --device NAME (any part "
          "of its name).\n"})
        EXPECT_NE(run.out.find(field), std::string::npos) << field << " missing from " << run.out;
    // The limits are numbers, one line each, as lavapipe reports them.
    EXPECT_TRUE(std::regex_search(run.out, std::regex("\n  maxImageDimension2D: [0-9]+\n")))
        << run.out;
    // A scene named too changes nothing: the list, and no render.
    const ProcessResult withScene = runRaytracer({"x.scene", "--list-devices"});
    EXPECT_EQ(withScene.exitCode, 0) << withScene.err;
    EXPECT_EQ(withScene.out, run.out);
}

TEST(Quiet, ARenderLeavesStderrEmpty) {
    const std::filesystem::path dir = freshOutputDir("cli-output/quiet");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    const std::vector<std::string> args = {scene.string(), "-o",        (dir / "out.png").string(),
                                           "--width",      "32",        "--height",
                                           "24",           "--progress"};
    const ProcessResult loud = runRaytracer(args);
    ASSERT_EQ(loud.exitCode, 0) << loud.err;
    EXPECT_NE(loud.err.find("Wrote "), std::string::npos) << "nothing for --quiet to take away";
    std::vector<std::string> quietArgs = args;
    quietArgs.push_back("--quiet");
    const ProcessResult quiet = runRaytracer(quietArgs);
    EXPECT_EQ(quiet.exitCode, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
    EXPECT_EQ(readPng(dir / "out.png").width, 32);
}

TEST(Quiet, WarningsArePrintedNoneErrorsStill) {
    const std::filesystem::path dir = freshOutputDir("cli-output/quiet-warnings");
    std::string text = minimalScene();
    text.replace(text.find("spe: 0.3 0.3 0.3"), 16, "spe: 1.5 0.3 0.3"); // warned, not refused
    const std::filesystem::path scene = writeScene(dir, text);
    const std::vector<std::string> args = {scene.string(), "-o",     (dir / "out.png").string(),
                                           "--width",      "32",     "--height",
                                           "24",           "--quiet"};
    const ProcessResult warned = runRaytracer(args);
    EXPECT_EQ(warned.exitCode, 0) << warned.err;
    EXPECT_EQ(warned.err, "");
    ProcessResult loud = runRaytracer({scene.string(), "--check"});
    EXPECT_NE(loud.err.find(":7: warning: "), std::string::npos) << loud.err;
    ProcessResult checked = runRaytracer({scene.string(), "--check", "--quiet"});
    EXPECT_EQ(checked.exitCode, 0) << checked.err;
    EXPECT_EQ(checked.err, "");

    // Errors print whatever --quiet says: a malformed scene, a runtime failure.
    const std::filesystem::path bad = dir / "bad.scene";
    writeTextFile(bad, "1\namb: 0 0 0\nsphere\npos: 0 0 -3\nradius: 1\n");
    const ProcessResult malformed = runRaytracer({bad.string(), "--quiet", "-o", "x.png"}, 60, dir);
    EXPECT_EQ(malformed.exitCode, 3);
    EXPECT_EQ(malformed.err.rfind(bad.string() + ":5: error: ", 0), 0u) << malformed.err;
    const ProcessResult failed = runRaytracer(
        {scene.string(), "--quiet", "-o", (dir / "y.png").string(), "--device", "no-such-gpu"});
    EXPECT_EQ(failed.exitCode, 1);
    EXPECT_EQ(failed.err.rfind("error: --device no-such-gpu matches no Vulkan device. Found:", 0),
              0u)
        << failed.err;
}

// Without a display, SCENE renders to ./STEM.png; an existing one is kept and the next
// free STEM-N.png is written instead, and named.
TEST(NoDisplay, TheFallbackNeverReplacesAnEarlierRender) {
    const std::filesystem::path dir = freshOutputDir("cli-output/no-display");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    const std::vector<std::string> args = {scene.string(), "--width", "32", "--height", "24"};
    const ProcessResult first = runRaytracer(args, 300, dir);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_NE(first.err.find("No display: rendering headless to input.png\n"), std::string::npos)
        << first.err;
    const std::string earlier = readWholeFile(dir / "input.png");
    for (const char* next : {"input-1.png", "input-2.png"}) {
        const ProcessResult again = runRaytracer(args, 300, dir);
        ASSERT_EQ(again.exitCode, 0) << again.err;
        EXPECT_NE(again.err.find(std::string("No display: rendering headless to ") + next +
                                 " (input.png exists and is kept)\n"),
                  std::string::npos)
            << again.err;
        EXPECT_NE(again.err.find(std::string("Wrote ") + next + "\n"), std::string::npos)
            << again.err;
        EXPECT_EQ(readWholeFile(dir / "input.png"), earlier);
        EXPECT_EQ(readWholeFile(dir / next), earlier) << "the same render, another name";
    }
}

// Lines that start with prefix, without it.
std::vector<std::string> linesStartingWith(const std::string& text, const std::string& prefix) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);)
        if (line.rfind(prefix, 0) == 0) lines.push_back(line);
    return lines;
}

// Not a terminal: a plain line every RAYTRACER_PROGRESS_INTERVAL seconds (0 here: after each
// of the 80 regions that --region-size 16 makes of 160 x 120), then the summary line.
TEST(Progress, PlainLinesWhenStderrIsNotATerminal) {
    const std::filesystem::path dir = freshOutputDir("cli-output/progress");
    const std::string scene = std::string(PROJECT_SCENES_DIR) + "/showcase.scene";
    setenv("RAYTRACER_PROGRESS_INTERVAL", "0", 1);
    const ProcessResult run =
        runRaytracer({scene, "-o", (dir / "out.png").string(), "--width", "160", "--height", "120",
                      "--region-size", "16", "--progress"});
    const ProcessResult shortRun = runRaytracer(
        {scene, "-o", (dir / "short.png").string(), "--width", "16", "--height", "12"});
    unsetenv("RAYTRACER_PROGRESS_INTERVAL");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> lines = linesStartingWith(run.err, "progress: ");
    EXPECT_GE(lines.size(), 40u) << run.err;
    const std::regex format("progress: ([0-9]{1,2})% ([0-9]+\\.[0-9]) s elapsed, about "
                            "([0-9]+\\.[0-9]) s left");
    int lastPercent = -1;
    for (const std::string& line : lines) {
        std::smatch parts;
        ASSERT_TRUE(std::regex_match(line, parts, format)) << "'" << line << "'";
        const int percent = std::stoi(parts[1]);
        EXPECT_GE(percent, lastPercent) << line;
        lastPercent = percent;
    }
    EXPECT_GE(lastPercent, 90) << run.err;
    EXPECT_EQ(linesStartingWith(run.err, "Rendered 160x120 in ").size(), 1u) << run.err;
    EXPECT_EQ(run.err.find('\r'), std::string::npos) << "no redraws off a terminal";
    // A short render without --progress stays quiet, whatever the interval.
    ASSERT_EQ(shortRun.exitCode, 0) << shortRun.err;
    EXPECT_EQ(shortRun.err.find("progress: "), std::string::npos) << shortRun.err;
    EXPECT_EQ(shortRun.err.find("Rendered "), std::string::npos) << shortRun.err;
}

// The start-up's phases report as renders do: with --progress each says when it is done
// (and, past a tenth of a second, how far it is); a benchmark and --quiet say nothing.
TEST(Progress, TheStartUpsPhasesSayWhenTheyAreDone) {
    const std::filesystem::path dir = freshOutputDir("cli-output/phase-progress");
    const std::filesystem::path model = dir / "m.obj";
    writeTextFile(model, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    const std::vector<std::string> args = {
        model.string(), "-o", (dir / "out.png").string(), "--width", "16", "--height", "12"};
    std::vector<std::string> asked = args;
    asked.push_back("--progress");
    const ProcessResult run = runRaytracer(asked);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (const std::string& phase :
         {"Reading " + model.string(), "Making a mesh of " + model.string(),
          std::string("Packing the scene"), std::string("Building the hierarchy")})
        EXPECT_EQ(linesStartingWith(run.err, phase + ": done in ").size(), 1u)
            << phase << " in " << run.err;
    std::vector<std::string> bench = asked;
    bench.insert(bench.end(), {"--bench", "1"});
    std::vector<std::string> quiet = asked;
    quiet.push_back("--quiet");
    for (const auto& silent : {bench, quiet}) {
        const ProcessResult other = runRaytracer(silent);
        ASSERT_EQ(other.exitCode, 0) << other.err;
        EXPECT_EQ(other.err.find("done in"), std::string::npos) << other.err;
    }
}

} // namespace
