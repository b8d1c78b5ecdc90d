// The command line as a user meets it: help, usage errors, bad scene files (clear
// message, non-zero exit, no image written), device choice and --bench output.
#include "model/scene_file.h"
#include "scene/scene_loader.h"
#include "test_support.h"

#include <glm/vec2.hpp>
#include <glslang/build_info.h>
#include <gtest/gtest.h>
#include <vulkan/vulkan_core.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>

namespace {

std::string minimalScene() {
    return "2\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -3\nrad: 1\ndif: 0.5 0.2 0.2\nspe: 0.3 0.3 0.3\n"
           "shi: 10\nlight\npos: 2 2 0\ncol: 1 1 1\n";
}

std::filesystem::path writeScene(const std::filesystem::path& dir, const std::string& text) {
    std::filesystem::path path = dir / "input.scene";
    writeTextFile(path, text);
    return path;
}

TEST(CommandLine, HelpPrintsUsageAndSucceeds) {
    ProcessResult run = runRaytracer({"--help"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_NE(run.out.find("Usage: Raytracer SCENE"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("--bench N"), std::string::npos);
    for (const char* option :
         {"--sampler grid|stratified|r2", "--seed N", "--precision fp32|fp64",
          "--sphere-test naive|stable", "--triangle-test mt|watertight", "--offset fixed|scaled",
          "--crop X,Y,W,H", "--turntable N", "--camera-path FILE", "--frames FIRST-LAST",
          "Raytracer SCENE... -o 'out/{name}.png'"})
        EXPECT_NE(run.out.find(option), std::string::npos) << option << " missing from " << run.out;
}

// The lines expected from CMake's project() VERSION and the headers this test was built with
// (the same packages as the program's).
std::string expectedVersionText() {
    const std::uint32_t vulkan = VK_HEADER_VERSION_COMPLETE;
    return "Raytracer " RAYTRACER_VERSION "\nVulkan headers " +
           std::to_string(VK_API_VERSION_MAJOR(vulkan)) + "." +
           std::to_string(VK_API_VERSION_MINOR(vulkan)) + "." + std::to_string(VK_HEADER_VERSION) +
           "\nglslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." +
           std::to_string(GLSLANG_VERSION_MINOR) + "." + std::to_string(GLSLANG_VERSION_PATCH) +
           "\n";
}

TEST(CommandLine, VersionNamesTheProgramVulkanAndGlslang) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"--version"}, {"x.scene", "--version", "--width", "8"}}) {
        ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(run.out, expectedVersionText());
        EXPECT_EQ(run.err, ""); // no "Device:" line: no Vulkan instance was made
    }
}

TEST(CommandLine, MissingSceneArgumentIsAUsageError) {
    ProcessResult run = runRaytracer({});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("error: no scene file given"), std::string::npos) << run.err;
}

TEST(CommandLine, BadOptionValuesAreUsageErrors) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"x.scene", "--width", "0"}, "--width expects a whole number from 1 to 65536, got '0'"},
        {{"x.scene", "--height", "-5"},
         "--height expects a whole number from 1 to 65536, got '-5'"},
        {{"x.scene", "--spp", "abc"}, "--spp expects a whole number from 1 to 65536, got 'abc'"},
        {{"x.scene", "--depth", "65"}, "--depth expects a whole number from 0 to 64, got '65'"},
        {{"x.scene", "--fov", "180"}, "--fov expects degrees strictly between 0 and 180"},
        {{"x.scene", "--background", "1,1"},
         "--background expects three non-negative numbers R,G,B, got '1,1'"},
        {{"x.scene", "--width"}, "--width expects a value"},
        {{"x.scene", "--frobnicate"}, "unknown option '--frobnicate'"},
        {{"a.scene", "b.scene"},
         "'b.scene' is no file: each argument without an option is a scene to render"},
        {{"x.scene", "--sampler", "halton"},
         "--sampler expects grid, stratified or r2, got 'halton'"},
        {{"x.scene", "--seed", "-1"},
         "--seed expects a whole number from 0 to 4294967295, got '-1'"},
        {{"x.scene", "--precision", "fp16"}, "--precision expects fp32 or fp64, got 'fp16'"},
        {{"x.scene", "--sphere-test", "fast"}, "--sphere-test expects naive or stable, got 'fast'"},
        {{"x.scene", "--triangle-test", "MT"},
         "--triangle-test expects mt or watertight, got 'MT'"},
        {{"x.scene", "--offset", "1e-4"},
         "--offset expects fixed, scaled or error-bound, got '1e-4'"},
        {{"x.scene", "--sampler"}, "--sampler expects a value"},
        {{"x.scene", "--threads", "0"}, "--threads expects a whole number from 1 to 256, got '0'"},
    };
    for (const auto& [args, message] : cases) {
        ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2) << message;
        EXPECT_NE(run.err.find("error: " + message), std::string::npos) << run.err;
    }
}

// A usage error is two lines: the error, then where the options are listed (not the whole
// help, which would scroll the error out of sight).
TEST(CommandLine, UsageErrorIsTheErrorAndOneLineToTheHelp) {
    const std::string seeHelp = "Run 'Raytracer --help' for the list of options.\n";
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"x.scene", "--widht", "800"}, "error: unknown option '--widht'; did you mean --width?\n"},
        {{"x.scene", "--offst=scaled"},
         "error: unknown option '--offst'; did you mean --offset?\n"},
        {{"x.scene", "--frobnicate"}, "error: unknown option '--frobnicate'\n"},
        {{"x.scene", "--validate=yes"}, "error: --validate takes no value, got '--validate=yes'\n"},
        {{"x.scene", "--width=0"},
         "error: --width expects a whole number from 1 to 65536, got '0'\n"},
        {{}, "error: no scene file given\n"},
    };
    for (const auto& [args, message] : cases) {
        ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_EQ(run.err, message + seeHelp);
        EXPECT_EQ(run.out, "");
    }
}

// Command lines that would do something other than their writer meant: a model's options on a
// scene file, and an output written without -o (which reads as a second scene).
TEST(CommandLine, MeaninglessCombinationsSayWhatWasMeant) {
    const std::filesystem::path dir = freshOutputDir("cli/meant");
    const std::string scene = writeScene(dir, minimalScene()).string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{scene, "--up", "z", "-o", "a.png"},
         "error: --up shapes a model, and " + scene +
             " is a scene file, whose own triangles, lights and camera are used as they are\n"},
        {{scene, "--no-ground", "--crease", "0", "--no-ground"},
         "error: --no-ground and --crease shape a model, and " + scene +
             " is a scene file, whose own triangles, lights and camera are used as they are\n"},
        {{scene, "out.png"},
         "error: 'out.png' is no file: each argument without an option is a "
         "scene to render; to write the image there, give -o out.png\n"},
        {{scene, "other.scene"},
         "error: 'other.scene' is no file: each argument without an "
         "option is a scene to render\n"},
        {{scene, scene},
         "error: several scenes would all write no file: give -o a pattern with "
         "{name}, the scene file's stem (out/{name}.png), or a folder (out/)\n"},
    };
    for (const auto& [args, message] : cases) {
        ProcessResult run = runRaytracer(args, 60, dir);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_EQ(run.err, message + "Run 'Raytracer --help' for the list of options.\n");
        EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
    }
}

// --opt=value renders what --opt value renders: the same bytes.
TEST(CommandLine, OptionEqualsValueRendersAsTwoWords) {
    std::filesystem::path dir = freshOutputDir("cli/equals");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    const std::string joined = (dir / "joined.png").string(), split = (dir / "split.png").string();
    ProcessResult a = runRaytracer(
        {scene.string(), "--output=" + joined, "--width=24", "--height=18", "--offset=scaled"});
    ProcessResult b = runRaytracer(
        {scene.string(), "-o", split, "--width", "24", "--height", "18", "--offset", "scaled"});
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(readPng(joined).width, 24);
    EXPECT_EQ(readWholeFile(joined), readWholeFile(split));
}

// --check on a scene written here, whose counts and box are known from its text: two
// spheres sharing a material, a triangle with a zero normal and two vertex materials, two
// lights (outside the box, which holds only what rays can hit).
TEST(CommandLine, CheckPrintsWhatTheSceneHolds) {
    std::filesystem::path dir = freshOutputDir("cli/check");
    const std::string vertex = "dif: 0.5 0.5 0.5\nspe: 0 0 0\nshi: 1\n";
    const std::string other = "dif: 0.25 0.5 1\nspe: 0.125 0 0\nshi: 8\n";
    const std::string text = "5\namb: 0.1 0.1 0.1\n"
                             "sphere\npos: 0 0 -3\nrad: 1\n" +
                             vertex + "sphere\npos: 2 0.5 -4\nrad: 0.5\n" + vertex +
                             "triangle\npos: -2 -1 -5\nnor: 0 0 0\n" + vertex +
                             "pos: 1 -1 -5\nnor: 0 0 1\n" + other + "pos: 0 3 -5\nnor: 0 0 1\n" +
                             vertex +
                             "light\npos: 10 10 10\ncol: 1 1 1\nlight\npos: -9 0 0\ncol: 1 1 1\n";
    const std::filesystem::path scene = writeScene(dir, text);
    ProcessResult run = runRaytracer({scene.string(), "--check"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out, scene.string() + ": valid\n"
                                        "spheres: 2\ntriangles: 1\nlights: 2\nmaterials: 2\n"
                                        "bounds: -2,-1,-5 to 2.5,3,-2\nwarnings: 1\n");
    // The warning as a render prints it, and nothing of Vulkan ("Device: ...").
    EXPECT_EQ(run.err,
              scene.string() + ":17: warning: the triangle's vertex 1 normal has zero length\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "input.png"));
}

// A mesh of 35,000 zero normals: twenty of them on stderr, then one line for the rest.
TEST(CommandLine, ManyWarningsOfAKindAreSummarised) {
    std::filesystem::path dir = freshOutputDir("cli/many-warnings");
    const int count = 35000;
    std::string text = std::to_string(count) + "\namb: 0 0 0\n";
    const std::string material = "dif: 0.5 0.5 0.5\nspe: 0 0 0\nshi: 1\n";
    for (int i = 0; i < count; ++i)
        text += "triangle\npos: 0 0 -1\nnor: 0 0 0\n" + material + "pos: 1 0 -1\nnor: 0 0 1\n" +
                material + "pos: 0 1 -1\nnor: 0 0 1\n" + material;
    const std::filesystem::path scene = writeScene(dir, text);
    ProcessResult run = runRaytracer({scene.string(), "--check"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    std::string expected;
    for (int i = 0; i < 20; ++i) // triangle i's first normal is on line 5 + 16 i
        expected += scene.string() + ":" + std::to_string(5 + 16 * i) +
                    ": warning: the triangle's vertex 1 normal has zero length\n";
    expected += scene.string() + ": warning: ... and 34,980 more warnings that the triangle's "
                                 "vertex N normal has zero length\n";
    EXPECT_EQ(run.err, expected);
    EXPECT_NE(run.out.find("\nwarnings: 35000\n"), std::string::npos) << run.out;
}

// -o into a folder that is not there names the folder, before any Vulkan.
TEST(CommandLine, MissingOutputFolderIsNamed) {
    std::filesystem::path dir = freshOutputDir("cli/missing-folder");
    const std::filesystem::path scene = writeScene(dir, minimalScene());
    ProcessResult run = runRaytracer({scene.string(), "-o", "missing/dir/out.png"}, 60, dir);
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_EQ(run.err, "error: missing/dir/out.png: the folder missing/dir does not exist\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    // Once the folder exists the same command writes the image.
    std::filesystem::create_directories(dir / "missing" / "dir");
    ProcessResult again = runRaytracer(
        {scene.string(), "-o", "missing/dir/out.png", "--width", "8", "--height", "6"}, 60, dir);
    EXPECT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(readPng(dir / "missing" / "dir" / "out.png").width, 8);
}

// A malformed scene: status 3 and the very message a render gives, before any Vulkan.
TEST(CommandLine, CheckReportsAMalformedSceneAsARenderDoes) {
    std::filesystem::path dir = freshOutputDir("cli/check-malformed");
    const std::filesystem::path scene =
        writeScene(dir, "1\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -3\nrad: -1\n");
    ProcessResult check = runRaytracer({scene.string(), "--check"});
    ProcessResult render = runRaytracer({scene.string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(check.exitCode, 3) << check.err;
    EXPECT_EQ(render.exitCode, 3) << render.err;
    EXPECT_EQ(check.err, render.err);
    EXPECT_EQ(check.err.rfind(scene.string() + ":5: error: ", 0), 0u) << check.err;
    EXPECT_EQ(check.out, "");
    ProcessResult combined = runRaytracer({scene.string(), "--check", "-o", "x.png"});
    EXPECT_EQ(combined.exitCode, 2);
    EXPECT_EQ(combined.err, "error: --check renders nothing and cannot be combined with -o, "
                            "--bench, --bench-window, --pixel or --window\n"
                            "Run 'Raytracer --help' for the list of options.\n");
}

TEST(CommandLine, MissingSceneFileNamesTheFileAndWritesNothing) {
    std::filesystem::path dir = freshOutputDir("cli/missing");
    std::filesystem::path output = dir / "out.png";
    ProcessResult run = runRaytracer({(dir / "nope.scene").string(), "-o", output.string()});
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_NE(run.err.find((dir / "nope.scene").string() + ": error: cannot open file"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(CommandLine, MalformedSceneNamesFileAndLineAndWritesNothing) {
    std::filesystem::path dir = freshOutputDir("cli/malformed");
    std::filesystem::path scene =
        writeScene(dir, "1\namb: 0 0 0\nsphere\npos: 0 0 -3\nradius: 1\n");
    std::filesystem::path output = dir / "out.png";
    ProcessResult run = runRaytracer({scene.string(), "-o", output.string()});
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_NE(run.err.find(scene.string() + ":5: error: "), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(output));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png.tmp"));
}

TEST(CommandLine, WarningsArePrintedAndTheRenderGoesOn) {
    std::filesystem::path dir = freshOutputDir("cli/warning");
    std::string text = minimalScene();
    text.replace(text.find("spe: 0.3 0.3 0.3"), 16, "spe: 1.5 0.3 0.3");
    std::filesystem::path scene = writeScene(dir, text);
    ProcessResult run = runRaytracer({scene.string(), "-o", (dir / "out.png").string(), "--width",
                                      "32", "--height", "24", "--validate"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find(scene.string() + ":7: warning: "), std::string::npos) << run.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
}

TEST(CommandLine, UnknownDeviceListsTheDevicesFound) {
    std::filesystem::path dir = freshOutputDir("cli/device");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    ProcessResult run =
        runRaytracer({scene.string(), "-o", (dir / "out.png").string(), "--device", "no-such-gpu"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("--device no-such-gpu matches no Vulkan device. Found:"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("llvmpipe"), std::string::npos) << run.err;
}

TEST(CommandLine, DeviceByIndexAndNameIsUsedAndPrinted) {
    std::filesystem::path dir = freshOutputDir("cli/device-choice");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    for (std::string request : {"0", "llvmpipe"}) {
        ProcessResult run =
            runRaytracer({scene.string(), "-o", (dir / "out.png").string(), "--device", request,
                          "--width", "32", "--height", "24", "--validate"});
        EXPECT_EQ(run.exitCode, 0) << run.err;
        EXPECT_NE(run.err.find("Device: llvmpipe"), std::string::npos) << run.err;
    }
}

// The worker threads lavapipe started in process pid: it names them llvmpipe-0, -1, ...
int cpuDriverThreads(pid_t pid) {
    int count = 0;
    std::error_code error;
    const std::filesystem::path tasks = "/proc/" + std::to_string(pid) + "/task";
    for (const auto& task : std::filesystem::directory_iterator(tasks, error)) {
        std::ifstream comm(task.path() / "comm");
        std::string name;
        if (std::getline(comm, name) && name.rfind("llvmpipe-", 0) == 0) ++count;
    }
    return count;
}

TEST(CommandLine, ThreadsSetsTheCpuDriversWorkerCount) {
    std::filesystem::path dir = freshOutputDir("cli/threads");
    for (int threads : {1, 3}) {
        int seen = -1;
        std::vector<std::string> args = {std::string(PROJECT_SCENES_DIR) + "/mesh.scene", "-o",
                                         (dir / "out.png").string()};
        // A render of minutes, ended by the signal below once the count has been read.
        args.insert(args.end(), {"--width", "4096", "--height", "4096", "--spp", "16", "--threads",
                                 std::to_string(threads)});
        ProcessResult run =
            runRaytracerWhile(args, [&](pid_t pid, const std::filesystem::path& errPath) {
                // The driver starts its workers with the device, which is made before the
                // scene is uploaded; the count is read until it is the one asked for (the
                // threads may take a moment to name themselves), for at most a minute.
                waitForText(errPath, "Scene memory:");
                for (int tries = 0; tries < 3000; ++tries) {
                    seen = cpuDriverThreads(pid);
                    if (seen == threads) break;
                    std::this_thread::sleep_for(std::chrono::milliseconds(20));
                }
                kill(pid, SIGTERM);
            });
        EXPECT_EQ(seen, threads) << run.err;
        EXPECT_EQ(run.exitCode, 128 + SIGTERM) << run.err;
    }
}

TEST(CommandLine, WithoutDisplayTheWindowModeRendersHeadless) {
    std::filesystem::path dir = freshOutputDir("cli/no-display");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    ProcessResult run = runRaytracer({scene.string(), "--width", "32", "--height", "24"}, 300, dir);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("No display: rendering headless to input.png"), std::string::npos)
        << run.err;
    EXPECT_EQ(readPng(dir / "input.png").width, 32);
}

TEST(CommandLine, ValidationIsOnAndAnyMessageFailsTheRun) {
    // The clean runs of the other tests prove nothing unless the layer is really on
    // and its messages really fail the run: the best-practices checks (which the
    // project does not follow, e.g. small allocations) provoke some on purpose.
    std::filesystem::path dir = freshOutputDir("cli/validation");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    std::vector<std::string> args = {scene.string(), "-o",        (dir / "out.png").string(),
                                     "--width",      "16",        "--height",
                                     "16",           "--validate"};
    ProcessResult clean = runRaytracer(args);
    EXPECT_EQ(clean.exitCode, 0) << clean.err;
    EXPECT_NE(clean.err.find("Validation: VK_LAYER_KHRONOS_validation on"), std::string::npos)
        << clean.err;

    setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT", 1);
    ProcessResult noisy = runRaytracer(args);
    unsetenv("VK_LAYER_ENABLES");
    EXPECT_EQ(noisy.exitCode, 4) << noisy.err;
    EXPECT_NE(noisy.err.find("error: the validation layer printed"), std::string::npos)
        << noisy.err;
}

TEST(CommandLine, BenchPrintsOneJsonLineWithEveryKey) {
    std::filesystem::path dir = freshOutputDir("cli/bench");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    ProcessResult run = runRaytracer(
        {scene.string(), "--bench", "3", "--width", "64", "--height", "48", "--validate"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::string json = benchJson(run);
    for (const char* key : {"\"scene\"",
                            "\"width\": 64",
                            "\"height\": 48",
                            "\"spp\": 1",
                            "\"depth\": 5",
                            "\"frames\": 3",
                            "\"device\": \"llvmpipe",
                            "\"wall_ms_median\"",
                            "\"wall_ms_min\"",
                            "\"gpu_ms_median\"",
                            "\"startup_ms\"",
                            "\"gpu_bytes\"",
                            "\"texture_bytes\": 0",
                            "\"parse_ms\"",
                            "\"read_ms\"",
                            "\"pack_ms\"",
                            "\"hierarchy_ms\"",
                            "\"upload_ms\"",
                            "\"kernel_ms\"",
                            "\"submissions\"",
                            "\"sampler\": \"r2\"",
                            "\"seed\": 0",
                            "\"precision\": \"fp32\"",
                            "\"sphere_test\": \"stable\"",
                            "\"triangle_test\": \"watertight\"",
                            "\"offset\": \"error-bound\""})
        EXPECT_NE(json.find(key), std::string::npos) << key << " missing from " << json;
    EXPECT_EQ(json.find("null"), std::string::npos) << "lavapipe has timestamps: " << json;
}

// --bench N -o out.png writes the last timed frame: the same bytes as the plain render.
TEST(CommandLine, BenchWithAnOutputWritesItsLastFrame) {
    std::filesystem::path dir = freshOutputDir("cli/bench-output");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    const std::filesystem::path benched = dir / "benched.png", plain = dir / "plain.png";
    ProcessResult run = runRaytracer({scene.string(), "--bench", "2", "-o", benched.string(),
                                      "--width", "64", "--height", "48", "--validate"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(benchJson(run).find("\"frames\": 2"), std::string::npos) << run.out;
    ProcessResult reference =
        runRaytracer({scene.string(), "-o", plain.string(), "--width", "64", "--height", "48"});
    ASSERT_EQ(reference.exitCode, 0) << reference.err;
    EXPECT_EQ(readWholeFile(benched), readWholeFile(plain));
}

TEST(CommandLine, BenchReportsTheKernelChoices) {
    std::filesystem::path dir = freshOutputDir("cli/bench-choices");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    ProcessResult run = runRaytracer({scene.string(),
                                      "--bench",
                                      "1",
                                      "--width",
                                      "16",
                                      "--height",
                                      "16",
                                      "--validate",
                                      "--sampler",
                                      "grid",
                                      "--seed",
                                      "7",
                                      "--precision",
                                      "fp64",
                                      "--sphere-test",
                                      "naive",
                                      "--triangle-test",
                                      "mt",
                                      "--offset",
                                      "fixed"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::string json = benchJson(run);
    for (const char* key :
         {"\"sampler\": \"grid\"", "\"seed\": 7", "\"precision\": \"fp64\"",
          "\"sphere_test\": \"naive\"", "\"triangle_test\": \"mt\"", "\"offset\": \"fixed\""})
        EXPECT_NE(json.find(key), std::string::npos) << key << " missing from " << json;
}

TEST(CommandLine, SamplesPerPixelAverageJitteredSamples) {
    // With several samples per pixel the positions are the renderer's choice: r2 (the
    // default) and stratified place them off the cell centres the reference uses. Away
    // from edges both average the same smooth colour; on an edge a pixel's estimates may
    // differ by the weight of about two of its 16 samples.
    std::filesystem::path dir = freshOutputDir("cli/spp");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    ReferenceSettings settings;
    settings.width = 80;
    settings.height = 60;
    settings.spp = 16;
    Image8 reference = renderReference(loadScene(scene), settings);
    for (const std::string sampler : {"r2", "stratified"}) {
        ProcessResult run =
            runRaytracer({scene.string(), "-o", (dir / "out.png").string(), "--spp", "16",
                          "--sampler", sampler, "--width", "80", "--height", "60", "--validate"});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        ImageComparison comparison = compareImages(readPng(dir / "out.png"), reference, 2);
        std::printf("spp 16 %s: %s\n", sampler.c_str(), describe(comparison).c_str());
        EXPECT_GE(comparison.fractionWithinTolerance, 0.95) << sampler;
        EXPECT_LE(comparison.maxChannelDifference, 2 * 255 / 16 + 2) << sampler;
    }
}

// Renders the minimal scene at 40 x 30 with extra flags; returns the PNG's bytes.
std::vector<std::uint8_t> renderBytes(const std::filesystem::path& dir, const std::string& name,
                                      const std::vector<std::string>& extra) {
    std::filesystem::path scene = dir / "input.scene";
    if (!std::filesystem::exists(scene)) writeScene(dir, minimalScene());
    std::vector<std::string> args = {scene.string(), "-o",        (dir / (name + ".png")).string(),
                                     "--width",      "40",        "--height",
                                     "30",           "--validate"};
    args.insert(args.end(), extra.begin(), extra.end());
    ProcessResult run = runRaytracer(args);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return readPng(dir / (name + ".png")).rgba;
}

TEST(CommandLine, OneSampleIsThePixelCentreWhateverTheSampler) {
    std::filesystem::path dir = freshOutputDir("cli/sampler-spp1");
    std::vector<std::uint8_t> centre = renderBytes(dir, "default", {});
    for (const char* sampler : {"grid", "stratified", "r2"})
        EXPECT_EQ(renderBytes(dir, sampler, {"--sampler", sampler, "--seed", "9"}), centre)
            << sampler;
}

TEST(CommandLine, SamplersAreDeterministicAndTheSeedVariesTheJitter) {
    std::filesystem::path dir = freshOutputDir("cli/sampler-seed");
    for (const std::string sampler : {"grid", "stratified", "r2"}) {
        std::vector<std::string> flags = {"--spp", "16", "--sampler", sampler};
        std::vector<std::uint8_t> first = renderBytes(dir, sampler + "-a", flags);
        EXPECT_EQ(renderBytes(dir, sampler + "-b", flags), first)
            << sampler << ": same command, other image";
        flags.insert(flags.end(), {"--seed", "12345"});
        std::vector<std::uint8_t> seeded = renderBytes(dir, sampler + "-seeded", flags);
        if (sampler == "grid")
            EXPECT_EQ(seeded, first) << "the grid has no jitter for a seed to change";
        else
            EXPECT_NE(seeded, first) << sampler << ": the seed changed nothing";
    }
}

TEST(CommandLine, GridSamplerMatchesTheReferenceGrid) {
    // The reference averages the centres of the same most nearly square grid (4 x 4 here), so
    // the grid sampler's image must match it as closely as one sample per pixel does.
    std::filesystem::path dir = freshOutputDir("cli/sampler-grid");
    std::filesystem::path scene = writeScene(dir, minimalScene());
    ProcessResult run =
        runRaytracer({scene.string(), "-o", (dir / "out.png").string(), "--spp", "16", "--sampler",
                      "grid", "--width", "80", "--height", "60", "--validate"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    ReferenceSettings settings;
    settings.width = 80;
    settings.height = 60;
    settings.spp = 16;
    ImageComparison comparison =
        compareImages(readPng(dir / "out.png"), renderReference(loadScene(scene), settings), 2);
    std::printf("grid spp 16: %s\n", describe(comparison).c_str());
    EXPECT_GE(comparison.fractionWithinTolerance, 0.995);
}

// The most primitives the brute-force path takes, with baked spheres
// (shaders/baked_spheres.glsl): 7 mirror spheres and 8 triangles, and 4 lights.
std::string largestBakedScene() {
    std::string text = "amb: 0.1 0.1 0.1\n";
    for (int i = 0; i < 7; ++i)
        text += "sphere\npos: " + std::to_string(i - 3) +
                " 0 -4\nrad: 0.45\n"
                "dif: 0.5 0.2 0.2\nspe: 0.3 0.3 0.3\nshi: 20\n";
    for (int i = 0; i < 8; ++i) {
        const double x = i - 4.0, z = -5.0 - i % 2;
        text += "triangle\n";
        for (const glm::dvec2 corner :
             {glm::dvec2(x - 0.5, -1.5), glm::dvec2(x + 0.5, -1.5), glm::dvec2(x, -0.5)})
            text += "pos: " + std::to_string(corner.x) + " " + std::to_string(corner.y) + " " +
                    std::to_string(z) + "\nnor: 0 1 0.5\ndif: 0.2 0.5 0.2\nspe: 0 0 0\nshi: 1\n";
    }
    for (int i = 0; i < 4; ++i)
        text += "light\npos: " + std::to_string(2 * i - 3) + " 3 0\ncol: 0.3 0.3 0.3\n";
    return "19\n" + text;
}

// --general-kernel (hidden, for tools/kernel_costs) keeps in what the scene does not need:
// it may cost time, never a pixel. Without ks: highlight and reflection loop compiled out
// of the specialised kernel; with ks but no triangles: the triangle code. All three scenes
// are small enough for their spheres to be baked into the specialised kernel, which the
// general one never does.
TEST(CommandLine, GeneralKernelGivesTheSameBytes) {
    std::filesystem::path dir = freshOutputDir("cli/general-kernel");
    const std::string matte =
        "3\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -3\nrad: 1\ndif: 0.5 0.2 0.2\nspe: 0 0 0\nshi: 10\n"
        "triangle\npos: -2 -1 -4\nnor: 0 1 0\ndif: 0.2 0.5 0.2\nspe: 0 0 0\nshi: 1\n"
        "pos: 2 -1 -4\nnor: 0 1 0\ndif: 0.2 0.5 0.2\nspe: 0 0 0\nshi: 1\n"
        "pos: 0 2 -5\nnor: 0 1 0\ndif: 0.2 0.5 0.2\nspe: 0 0 0\nshi: 1\n"
        "light\npos: 2 2 0\ncol: 1 1 1\n";
    const std::vector<std::pair<std::string, std::string>> scenes = {
        {"matte", matte}, {"shiny", minimalScene()}, {"largest-baked", largestBakedScene()}};
    for (const auto& [name, text] : scenes) {
        std::filesystem::path scene = dir / (name + ".scene");
        writeTextFile(scene, text);
        std::string bytes[2];
        for (int general = 0; general < 2; ++general) {
            const std::filesystem::path png = dir / (name + std::to_string(general) + ".png");
            std::vector<std::string> args = {scene.string(), "-o", png.string(), "--width", "40",
                                             "--height",     "30", "--validate"};
            if (general) args.push_back("--general-kernel");
            ProcessResult run = runRaytracer(args);
            ASSERT_EQ(run.exitCode, 0) << run.err;
            bytes[general] = readWholeFile(png);
        }
        EXPECT_FALSE(bytes[0].empty());
        EXPECT_EQ(bytes[0], bytes[1]) << name << ": the general kernel changed the image";

        // The flag did change the kernel: --bench names what the specialised one left out.
        for (const bool general : {false, true}) {
            std::vector<std::string> args = {scene.string(), "--bench",  "1", "--width",
                                             "16",           "--height", "16"};
            if (general) args.push_back("--general-kernel");
            ProcessResult run = runRaytracer(args);
            ASSERT_EQ(run.exitCode, 0) << run.err;
            const std::string json = benchJson(run);
            const std::string specialised = name == "matte"   ? "[\"highlight\", \"mirrors\"]"
                                            : name == "shiny" ? "[\"triangles\"]"
                                                              : "[]";
            const std::string expected =
                general ? "\"general_kernel\": true, \"compiled_out\": []"
                        : "\"general_kernel\": false, \"compiled_out\": " + specialised;
            EXPECT_NE(json.find(expected), std::string::npos)
                << expected << " missing from " << json;
            const std::string baked =
                general ? "\"baked_spheres\": false" : "\"baked_spheres\": true";
            EXPECT_NE(json.find(baked), std::string::npos) << baked << " missing from " << json;
        }
    }
}

TEST(CommandLine, GeneralKernelIsNotInTheUsageText) {
    EXPECT_EQ(runRaytracer({"--help"}).out.find("--general-kernel"), std::string::npos);
}

} // namespace
