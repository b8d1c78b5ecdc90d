// Batches, animation and regions (docs/batches.md): many scenes in one process give each
// scene's own render byte for byte; a scene that does not load is reported and skipped;
// turntable frame 0 and a camera-path line spelling the default camera give the plain
// render; camera-path errors word for word; --crop regions stitched give the full image
// for every sampler, and a poster beyond the device's image limit renders so; the usage errors of
// patterns and regions word for word.
#include "base/float_image.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

namespace fs = std::filesystem;

const fs::path kShowcase = fs::path(PROJECT_SCENES_DIR) / "showcase.scene";
const std::string kSeeHelp = "Run 'Raytracer --help' for the list of options.\n";

// A small image with the validation layer on: any message fails the run.
std::vector<std::string> small(std::vector<std::string> args) {
    for (const char* word : {"--width", "48", "--height", "36", "--validate"})
        args.push_back(word);
    return args;
}

// The classic scenes when they are there, else the project's (without the large mesh).
std::vector<fs::path> batchScenes() {
    std::vector<fs::path> scenes = sceneFilesIn(SHARED_SCENES_DIR);
    if (scenes.empty()) {
        scenes = sceneFilesIn(PROJECT_SCENES_DIR);
        std::erase_if(scenes, [](const fs::path& scene) { return scene.stem() == "mesh"; });
    }
    return scenes;
}

// Renders scene alone to file; the run must succeed.
void renderAlone(const fs::path& scene, const fs::path& file, std::vector<std::string> more = {}) {
    std::vector<std::string> args = {scene.string(), "-o", file.string()};
    args.insert(args.end(), more.begin(), more.end());
    const ProcessResult run = runRaytracer(small(args));
    ASSERT_EQ(run.exitCode, 0) << run.err;
}

void expectSameFile(const fs::path& a, const fs::path& b) {
    const std::string first = readWholeFile(a), second = readWholeFile(b);
    EXPECT_FALSE(first.empty()) << a;
    EXPECT_TRUE(first == second) << a << " and " << b << " differ";
}

TEST(Batch, EachImageIsTheSingleSceneRenderByteForByte) {
    const fs::path dir = freshOutputDir("batch/scenes");
    const std::vector<fs::path> scenes = batchScenes();
    ASSERT_GE(scenes.size(), 2u);
    std::vector<std::string> args;
    for (const fs::path& scene : scenes)
        args.push_back(scene.string());
    std::vector<std::string> patterned = args, folder = args;
    for (const std::string& word : {std::string("-o"), (dir / "p-{name}.png").string()})
        patterned.push_back(word);
    for (const std::string& word : {std::string("-o"), (dir / "folder/").string()})
        folder.push_back(word);
    fs::create_directories(dir / "folder");
    for (const auto& batchArgs : {patterned, folder}) {
        const ProcessResult run = runRaytracer(small(batchArgs));
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_NE(run.err.find("Batch: " + std::to_string(scenes.size()) + " image(s) of " +
                               std::to_string(scenes.size()) + " scene(s); kernels compiled "),
                  std::string::npos)
            << run.err;
    }
    for (const fs::path& scene : scenes) {
        const std::string name = scene.stem().string();
        renderAlone(scene, dir / ("alone-" + name + ".png"));
        expectSameFile(dir / ("alone-" + name + ".png"), dir / ("p-" + name + ".png"));
        expectSameFile(dir / ("alone-" + name + ".png"), dir / "folder" / (name + ".png"));
    }
}

// The same scene twice (under two names) compiles its kernel once.
TEST(Batch, AKernelOfTheSameSpecializationIsReused) {
    const fs::path dir = freshOutputDir("batch/reuse");
    fs::copy_file(kShowcase, dir / "again.scene");
    const ProcessResult run = runRaytracer(
        small({kShowcase.string(), (dir / "again.scene").string(), "-o", (dir / "").string()}));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("Batch: 2 image(s) of 2 scene(s); kernels compiled 1, reused 1\n"),
              std::string::npos)
        << run.err;
    expectSameFile(dir / "showcase.png", dir / "again.png");
}

TEST(Batch, ASceneThatDoesNotLoadIsReportedSkippedAndExits3) {
    const fs::path dir = freshOutputDir("batch/broken");
    const fs::path broken = dir / "broken.scene";
    writeTextFile(broken, "1\nsphere\npos: 0 0\n");
    const ProcessResult run =
        runRaytracer(small({kShowcase.string(), broken.string(),
                            (fs::path(PROJECT_SCENES_DIR) / "mirrors.scene").string(), "-o",
                            (dir / "{name}.png").string()}));
    EXPECT_EQ(run.exitCode, 3) << run.err;
    EXPECT_NE(run.err.find(broken.string() +
                           ":2: error: expected 'amb:' after the object count, found 'sphere'\n"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("Batch: 2 image(s) of 2 scene(s), 1 scene(s) not loaded; "),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(fs::exists(dir / "showcase.png"));
    EXPECT_TRUE(fs::exists(dir / "mirrors.png"));
    EXPECT_FALSE(fs::exists(dir / "broken.png"));
    EXPECT_FALSE(fs::exists(dir / "broken.png.tmp"));
}

TEST(Animation, TurntableFrameZeroIsThePlainRender) {
    const fs::path dir = freshOutputDir("batch/turntable");
    const ProcessResult run = runRaytracer(small(
        {kShowcase.string(), "--turntable", "3", "-o", (dir / "frame-{frame:04}.png").string()}));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    renderAlone(kShowcase, dir / "plain.png");
    expectSameFile(dir / "plain.png", dir / "frame-0000.png");
    EXPECT_TRUE(fs::exists(dir / "frame-0002.png"));
    EXPECT_FALSE(fs::exists(dir / "frame-0003.png"));
    EXPECT_NE(readWholeFile(dir / "plain.png"), readWholeFile(dir / "frame-0001.png"))
        << "the turntable did not turn";
    // --frames renders a share of them with their numbers: a farm's task.
    const ProcessResult share =
        runRaytracer(small({kShowcase.string(), "--turntable", "3", "--frames", "1-2", "-o",
                            (dir / "share-{frame}.png").string()}));
    ASSERT_EQ(share.exitCode, 0) << share.err;
    EXPECT_FALSE(fs::exists(dir / "share-0.png"));
    expectSameFile(dir / "frame-0001.png", dir / "share-1.png");
    expectSameFile(dir / "frame-0002.png", dir / "share-2.png");
}

TEST(Animation, ACameraPathLineOfTheDefaultCameraIsThePlainRender) {
    const fs::path dir = freshOutputDir("batch/camera-path");
    const fs::path path = dir / "path.txt";
    writeTextFile(path, "# position target up fov\n\n0,0,0 0,0,-1 0,1,0 60  # the default\n"
                        "\t1,0.5,0  0,0,-6\t0,1,0 45\n");
    const ProcessResult run =
        runRaytracer(small({kShowcase.string(), "--camera-path", path.string(), "-o",
                            (dir / "f{frame}.png").string()}));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    renderAlone(kShowcase, dir / "plain.png");
    expectSameFile(dir / "plain.png", dir / "f0.png");
    renderAlone(kShowcase, dir / "moved.png",
                {"--camera-pos", "1,0.5,0", "--camera-target", "0,0,-6", "--fov", "45"});
    expectSameFile(dir / "moved.png", dir / "f1.png");
}

TEST(Animation, CameraPathErrorsNameTheFileAndLineWordForWord) {
    const fs::path dir = freshOutputDir("batch/camera-path-errors");
    const fs::path path = dir / "path.txt";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"0,0,0 0,0,-1 0,1,0\n",
         ":1: error: expected 4 fields, POSITION TARGET UP FOV (as in 0,0,0 0,0,-1 0,1,0 60), "
         "got 3"},
        {"# one\n0,0 0,0,-1 0,1,0 60\n",
         ":2: error: position expects three numbers X,Y,Z, got '0,0'"},
        {"0,0,0 0,0,-1,2 0,1,0 60\n",
         ":1: error: target expects three numbers X,Y,Z, got '0,0,-1,2'"},
        {"0,0,0 0,0,-1 0,x,0 60\n", ":1: error: up expects three numbers X,Y,Z, got '0,x,0'"},
        {"0,0,0 0,0,-1 0,1,0 180\n",
         ":1: error: fov expects degrees strictly between 0 and 180, got '180'"},
        {"\n\n1,1,1 1,1,1 0,1,0 60\n",
         ":3: error: the camera target must differ from the camera position"},
        {"0,0,0 0,1,0 0,1,0 60\n",
         ":1: error: the camera up vector must not be parallel to the view direction"},
        {"# nothing\n\n", ": error: no camera in the file (one a line: POSITION TARGET UP FOV)"},
    };
    for (const auto& [text, message] : cases) {
        writeTextFile(path, text);
        const ProcessResult run =
            runRaytracer(small({kShowcase.string(), "--camera-path", path.string(), "-o",
                                (dir / "f{frame}.png").string()}));
        EXPECT_EQ(run.exitCode, 3) << text;
        EXPECT_EQ(run.err, path.string() + message + "\n") << text;
    }
    const ProcessResult missing =
        runRaytracer(small({kShowcase.string(), "--camera-path", (dir / "none.txt").string(), "-o",
                            (dir / "f{frame}.png").string()}));
    EXPECT_EQ(missing.exitCode, 3);
    EXPECT_EQ(missing.err, (dir / "none.txt").string() +
                               ": error: cannot open file: No such file or directory\n");
    EXPECT_TRUE(sceneFilesIn(dir).empty());
    EXPECT_FALSE(fs::exists(dir / "f0.png"));
}

// Regions of 48 x 36 that meet at odd places, stitched by tools/stitch from their names.
TEST(Regions, CropsStitchedAreTheFullImageByteForByte) {
    const fs::path dir = freshOutputDir("batch/crop");
    const std::vector<std::vector<std::string>> samplings = {
        {},
        {"--spp", "4", "--sampler", "grid"},
        {"--spp", "3", "--sampler", "stratified", "--seed", "5"},
        {"--spp", "5", "--sampler", "r2"}};
    const std::vector<std::string> crops = {"0,0,17,13", "17,0,31,13", "0,13,30,23", "30,13,18,23"};
    for (std::size_t s = 0; s < samplings.size(); ++s) {
        const fs::path full = dir / ("full-" + std::to_string(s) + ".png");
        renderAlone(kShowcase, full, samplings[s]);
        std::vector<std::string> parts = {
            "-o", (dir / ("stitched-" + std::to_string(s) + ".png")).string()};
        for (const std::string& crop : crops) {
            const std::string x = crop.substr(0, crop.find(',')),
                              y = crop.substr(crop.find(',') + 1,
                                              crop.find(',', crop.find(',') + 1) - crop.find(',') -
                                                  1);
            const fs::path part = dir / ("part-" + std::to_string(s) + "-" + x + "-" + y + ".png");
            std::vector<std::string> more = samplings[s];
            more.insert(more.end(), {"--crop", crop});
            renderAlone(kShowcase, part, more);
            parts.push_back(part.string());
        }
        const ProcessResult stitch = runProgram(STITCH_BINARY, parts);
        ASSERT_EQ(stitch.exitCode, 0) << stitch.err;
        expectSameFile(full, dir / ("stitched-" + std::to_string(s) + ".png"));
    }
}

// A poster larger than the device's image limit (lowered to 20 pixels a side by the hidden
// --max-image-side) is refused whole, with a pointer to --crop, and renders in parts of at
// most 20 x 20 whose stitch is the whole image rendered under the real limit, byte for byte;
// a part's float output is the whole float image's region, bit for bit (the kernel writes
// a crop-sized image from its place in the full image).
TEST(Regions, APosterBeyondTheImageLimitRendersInPartsThatFit) {
    const fs::path dir = freshOutputDir("batch/poster");
    const std::vector<std::string> sampling = {"--spp", "3", "--sampler", "stratified"};
    renderAlone(kShowcase, dir / "whole.png", sampling);
    renderAlone(kShowcase, dir / "whole.pfm", sampling);
    std::vector<std::string> lowered = sampling;
    lowered.insert(lowered.end(), {"--max-image-side", "20"});
    const ProcessResult refused =
        runRaytracer(small({kShowcase.string(), "-o", (dir / "refused.png").string(), "--spp", "3",
                            "--max-image-side", "20"}));
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find("error: a 48x36 image exceeds this device's maxImageDimension2D "
                               "of 20 (llvmpipe"),
              std::string::npos)
        << refused.err;
    EXPECT_NE(refused.err.find("render it in --crop parts that fit, which tools/stitch joins"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "refused.png"));

    std::vector<std::string> parts = {"-o", (dir / "stitched.png").string()};
    const ImageF whole = readPfm(dir / "whole.pfm");
    for (const std::uint32_t y : {0u, 20u})
        for (const std::uint32_t x : {0u, 20u, 40u}) {
            const std::uint32_t width = std::min(20u, 48 - x), height = std::min(20u, 36 - y);
            const std::string crop = std::to_string(x) + "," + std::to_string(y) + "," +
                                     std::to_string(width) + "," + std::to_string(height);
            const std::string place = std::to_string(x) + "-" + std::to_string(y);
            std::vector<std::string> more = lowered;
            more.insert(more.end(), {"--crop", crop});
            renderAlone(kShowcase, dir / ("part-" + place + ".png"), more);
            renderAlone(kShowcase, dir / ("part-" + place + ".pfm"), more);
            parts.push_back((dir / ("part-" + place + ".png")).string());
            const ImageF part = readPfm(dir / ("part-" + place + ".pfm"));
            ASSERT_EQ(part.width, int(width));
            ASSERT_EQ(part.height, int(height));
            for (std::uint32_t row = 0; row < height; ++row)
                for (std::uint32_t column = 0; column < width * 3; ++column)
                    ASSERT_EQ(part.rgb[row * width * 3 + column],
                              whole.rgb[(y + row) * 48 * 3 + x * 3 + column])
                        << crop << " row " << row << " value " << column;
        }
    const ProcessResult stitch = runProgram(STITCH_BINARY, parts);
    ASSERT_EQ(stitch.exitCode, 0) << stitch.err;
    expectSameFile(dir / "whole.png", dir / "stitched.png");
}

TEST(Regions, StitchRefusesGapsAndOverlaps) {
    const fs::path dir = freshOutputDir("batch/stitch-errors");
    renderAlone(kShowcase, dir / "a-0-0.png", {"--crop", "0,0,10,10"});
    const ProcessResult gap = runProgram(STITCH_BINARY, {"-o", (dir / "out.png").string(), "--size",
                                                         "11x10", (dir / "a-0-0.png").string()});
    EXPECT_EQ(gap.exitCode, 1);
    EXPECT_EQ(gap.err, "stitch: pixel 10,0 of the 11x10 image is in no part\n");
    const ProcessResult overlap =
        runProgram(STITCH_BINARY, {"-o", (dir / "out.png").string(), (dir / "a-0-0.png").string(),
                                   (dir / "a-0-0.png").string() + "@9,0"});
    EXPECT_EQ(overlap.exitCode, 1);
    EXPECT_EQ(overlap.err, "stitch: pixel 9,0 is in both " + (dir / "a-0-0.png").string() +
                               " and " + (dir / "a-0-0.png").string() + "\n");
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(Batch, PatternAndRegionUsageErrorsWordForWord) {
    const std::string scene = kShowcase.string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{scene, "--crop", "600,0,41,10", "-o", "x.png"},
         "--crop 600,0,41,10 lies outside the 640x480 image: X+W must be at most 640 and Y+H at "
         "most 480"},
        {{scene, "--width", "32", "--height", "24", "--crop", "0,20,8,5", "-o", "x.png"},
         "--crop 0,20,8,5 lies outside the 32x24 image: X+W must be at most 32 and Y+H at most 24"},
        {{scene, "--crop", "0,0,0,4", "-o", "x.png"},
         "--crop expects a region X,Y,W,H (left column, top row, width and height; whole "
         "numbers, W and H from 1), got '0,0,0,4'"},
        {{scene, "--crop", "0,0,4,4"},
         "--crop renders a region headless: give -o, and neither --window nor --bench-window"},
        {{scene, "b.scene", "-o", "x.png"},
         "several scenes would all write x.png: give -o a pattern with {name}, the scene file's "
         "stem (out/{name}.png), or a folder (out/)"},
        {{scene, scene}, // (a second scene that is no file says so: cli_test)
         "several scenes would all write no file: give -o a pattern with {name}, the scene "
         "file's stem (out/{name}.png), or a folder (out/)"},
        {{scene, "--turntable", "8", "-o", "x.png"},
         "--turntable 8 renders frames, but -o x.png has no {frame}: give a pattern such as "
         "out/frame-{frame:04}.png"},
        {{scene, "--camera-path", "p.txt", "-o", "{name}.png"},
         "--camera-path renders frames, but -o {name}.png has no {frame}: give a pattern such "
         "as out/frame-{frame:04}.png"},
        {{scene, "--turntable", "4", "-o", "f{frame}.png", "--frames", "2-4"},
         "--frames 2-4 goes past the last frame of --turntable 4, 3"},
        {{scene, "--frames", "1", "-o", "x.png"},
         "--frames chooses frames of --turntable or --camera-path; neither was given"},
        {{scene, "-o", "x-{frame:4}.png"},
         "-o x-{frame:4}.png: unknown field {frame:4} (known: {name}, {frame}, {frame:04})"},
        {{scene, "a/showcase.scene", "-o", "{name}.png"},
         "'" + scene +
             "' and 'a/showcase.scene' are both named 'showcase' and would write the "
             "same files"},
        {{scene, "--turntable", "1", "-o", "-"},
         "-o - writes one PNG to stdout; several scenes, --turntable and --camera-path write "
         "files: give -o a pattern or a folder"},
        {{scene, "b.scene", "-o", "{name}.png", "--bench", "2"},
         "several scenes, --turntable and --camera-path render headless, one image after "
         "another, and cannot be combined with --bench, --bench-window, --pixel, --check, "
         "--save-scene or --window"},
        {{scene, "b.scene", "-o", "{name}.png", "--save-scene", "s.scene"},
         "several scenes, --turntable and --camera-path render headless, one image after "
         "another, and cannot be combined with --bench, --bench-window, --pixel, --check, "
         "--save-scene or --window"},
    };
    for (const auto& [args, message] : cases) {
        const ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2) << message;
        EXPECT_EQ(run.err, "error: " + message + "\n" + kSeeHelp);
    }
}

} // namespace
