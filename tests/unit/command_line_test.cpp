// The command line read and written back: for many option sets, parseOptions ->
// commandLine -> (a POSIX shell splits the words) -> parseOptions gives equal Options, and
// the text is the same when printed again. Also the window's headless command, word for
// word. No Vulkan, no window.
#include "cli/command_line.h"
#include "cli/option_suggestion.h"
#include "cli/options.h"
#include "cli/output_pattern.h"
#include "shared.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

Options parse(const std::vector<std::string>& words) {
    std::vector<const char*> argv = {"Raytracer"};
    for (const std::string& word : words)
        argv.push_back(word.c_str());
    return parseOptions(int(argv.size()), argv.data());
}

// The words a POSIX shell makes of command's arguments (after "Raytracer"): the quoting
// is checked by the shell itself, not by a second implementation of it.
std::vector<std::string> shellWords(const std::string& command) {
    const std::string program = "Raytracer";
    EXPECT_EQ(command.substr(0, program.size()), program) << command;
    const std::string script = "printf '%s\\0'" + command.substr(program.size());
    FILE* shell = popen(script.c_str(), "r");
    EXPECT_NE(shell, nullptr);
    if (!shell) return {};
    std::string output;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, shell)) > 0;)
        output.append(buffer, n);
    EXPECT_EQ(pclose(shell), 0) << script;
    std::vector<std::string> words;
    for (std::size_t start = 0, end; (end = output.find('\0', start)) != std::string::npos;
         start = end + 1)
        words.push_back(output.substr(start, end - start));
    return words;
}

// Folders for --shader-dir whose names a shell would misread unquoted.
std::filesystem::path shaderFolder(const std::string& name) {
    const std::filesystem::path folder =
        std::filesystem::path(TEST_OUTPUT_DIR) / "command-line" / name;
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "trace.comp") << "#version 460\n";
    return folder;
}

std::vector<std::vector<std::string>> optionSets() {
    const std::string odd = shaderFolder("it's a \"dir\" with $HOME, `x`, \\ and *").string();
    const std::string spaced = shaderFolder("my shaders").string();
    const std::string dashed = shaderFolder("-tab\there\nand a newline").string();
    std::vector<std::vector<std::string>> sets = {
        {"a.scene"},
        {"a.scene", "-o", "out.png"},
        {"scenes/my scene's \"copy\".scene", "-o", "out dir/it's.png"},
        {"ünïcode.scene", "--output", "~/x.png"},
        {"a.scene", "--width", "1", "--height", "16384"},
        {"a.scene", "--width", "1023", "--height", "7"},
        {"a.scene", "--spp", "1"},
        {"a.scene", "--spp", "65536"},
        {"a.scene", "--depth", "0"},
        {"a.scene", "--depth", std::to_string(MAX_DEPTH)},
        {"a.scene", "--fov", "33.3"},
        {"a.scene", "--fov", "1e-300"},
        {"a.scene", "--fov", "179.99999999999997"},
        {"a.scene", "--background", "0,0,0"},
        {"a.scene", "--background", "0.1,0.2,0.30000000000000004"},
        {"a.scene", "--background", "1e300,0,2.5"},
        {"a.scene", "--camera-pos", "1,2,3"},
        {"a.scene", "--camera-target", "0.1,0,-1"},
        {"a.scene", "--camera-up", "0,1,0.2"},
        {"a.scene", "--camera-pos", "-3.5,4,2e-7", "--camera-up", "1e-9,-1,0"},
        {"a.scene", "--camera-pos", "3,4,2", "--camera-target", "0,0,-8", "--camera-up", "0,1,0.2"},
        {"a.scene", "--camera-target", "0,0,-1"}, // the default target, but given
        {"a.scene", "--shader-dir", spaced},
        {"a.scene", "--shader-dir", odd},
        {"a.scene", "--shader-dir", dashed},
        {"a.scene", "--accel", "auto"},
        {"a.scene", "--accel", "bvh"},
        {"a.scene", "--accel", "none"},
        {"a.scene", "--device", "llvmpipe (LLVM 15.0.6, 256 bits)"},
        {"a.scene", "--device", "1"},
        {"a.scene", "--threads", "1"},
        {"a.scene", "--device", "0", "--threads", "256"},
        {"a.scene", "-o", "b.png", "--bench", "3"},
        {"a.scene", "--bench-window", "100000"},
        {"a.scene", "--region-size", "64"},
        {"a.scene", "--pixel", "0,0"},
        {"a.scene", "-o", "b.png", "--width", "20", "--height", "10", "--pixel", "19,9"},
        {"--dump-shaders", "dumped shaders"},
        {"a.scene", "b c.scene", "d/e.scene", "-o", "out/{name}.png"},
        {"a.scene", "b.scene", "-o", "folder/"},
        {"a.scene", "-o", "out/{name}-{frame:04}.exr", "--turntable", "12"},
        {"a.scene", "-o", "f{frame}.png", "--turntable", "1"},
        {"a.scene", "-o", "f{frame}.png", "--turntable", "9", "--frames", "2-5"},
        {"a.scene", "-o", "f{frame:09}.png", "--camera-path", "my path.txt", "--frames", "3"},
        {"a.scene", "-o", "part.png", "--crop", "0,0,1,1"},
        {"a.scene", "-o", "part.png", "--width", "33", "--height", "20", "--crop", "7,3,26,17"},
        {"--help"},
        {"--version"},
        {"a.scene", "--check"},
        {"model.obj", "--save-scene", "out dir/model.scene"},
        {"model.obj", "--save-scene", "m.scene", "-o", "m.png"},
        {"model.obj", "--up", "z", "--crease", "0", "--no-ground"},
        {"model.obj", "--up", "-x", "--crease", "180"},
        {"model.obj", "--crease", "12.5"},
        {"model.obj", "--view", "top", "--up", "Z"},
        {"model.obj", "--no-fit", "--camera-pos", "0,0,0"}, // the default camera, but given
        {"a.scene", "-o", "f{frame}.png", "--turntable", "4", "--orbit-center", "1,-2,3.5"},
        {"a.scene", "-o", "out.jpg", "--quality", "1"},
        {"a.scene", "-o", "o.JPEG", "--quality", "100"},
        {"a.scene", "-o", "out.jpg", "--quality", "90"}, // the default, but given
        {"a.scene", "-o", "out.ppm"},
        {"a.scene", "-o", "-"},
        {"--list-devices"},
        {"a.scene", "--list-devices", "--device", "0"},
        {"a.scene", "--quiet"},
        {"a.scene", "-o", "-", "--quiet", "--progress"},
        {"a.scene", "--validate", "--no-cache", "--progress", "--window", "--redraw-continuously",
         "--general-kernel", "--storage-reads", "--overlay"},
    };
    for (const char* seed : {"0", "7", "4294967295"})
        sets.push_back({"a.scene", "--seed", seed});
    const std::vector<std::pair<const char*, std::vector<const char*>>> choices = {
        {"--sampler", {"grid", "stratified", "r2"}},
        {"--precision", {"fp32", "fp64"}},
        {"--sphere-test", {"naive", "stable"}},
        {"--triangle-test", {"mt", "watertight"}},
        {"--offset", {"fixed", "scaled", "error-bound"}},
        {"--up", {"y", "-y", "z", "-z", "x", "-x"}},
    };
    for (const auto& [flag, names] : choices)
        for (const char* name : names) // --up shapes a model: a scene file refuses it
            sets.push_back({std::string(flag) == "--up" ? "a.obj" : "a.scene", flag, name});
    sets.push_back({"x y.scene",   "-o",
                    "o.png",       "--width",
                    "17",          "--height",
                    "9",           "--spp",
                    "5",           "--depth",
                    "2",           "--fov",
                    "47.5",        "--background",
                    "0.25,0.5,1",  "--camera-pos",
                    "0.5,-2,1e-3", "--camera-up",
                    "0,0.9,0.1",   "--sampler",
                    "grid",        "--seed",
                    "11",          "--precision",
                    "fp64",        "--sphere-test",
                    "naive",       "--triangle-test",
                    "mt",          "--offset",
                    "fixed",       "--shader-dir",
                    odd,           "--accel",
                    "none",        "--device",
                    "0",           "--bench",
                    "2",           "--region-size",
                    "32",          "--no-cache",
                    "--progress"});
    return sets;
}

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& word : words)
        text += "[" + word + "] ";
    return text;
}

TEST(CommandLine, ParsePrintParseGivesTheSameOptions) {
    for (const std::vector<std::string>& words : optionSets()) {
        const Options options = parse(words);
        const std::string command = commandLine(options);
        try {
            const Options again = parse(shellWords(command));
            EXPECT_TRUE(again == options) << "from " << joined(words) << "\nprinted " << command;
            EXPECT_EQ(commandLine(again), command) << "from " << joined(words);
        } catch (const UsageError& error) {
            ADD_FAILURE() << "from " << joined(words) << "\nprinted " << command
                          << "\nwhich does not parse: " << error.what();
        }
    }
}

TEST(CommandLine, DefaultsArePrintedOnlyWhereTheWindowAlwaysShowedThem) {
    EXPECT_EQ(commandLine(parse({"a.scene"})),
              "Raytracer a.scene --width 640 --height 480 --depth 5 --fov 60");
}

TEST(CommandLine, QuotesForAShellOnlyWhatNeedsIt) {
    EXPECT_EQ(shellQuoted("scenes/a-b_c.scene"), "scenes/a-b_c.scene");
    EXPECT_EQ(shellQuoted("a b"), "'a b'");
    EXPECT_EQ(shellQuoted("it's"), "'it'\\''s'");
    EXPECT_EQ(shellQuoted(""), "''");
    EXPECT_EQ(shellQuoted("~/x"), "'~/x'");
}

// The window's screenshot line: exactly the text it has always printed, and parsed again it
// asks for the same image.
TEST(ScreenshotCommand, ReproducesEveryChoiceThatChangesPixels) {
    const Options plain = parse({"a.scene"});
    EXPECT_EQ(headlessCommand(plain, plain.camera, 64, 48, 4),
              "Raytracer a.scene -o OUT.png --width 64 --height 48 --spp 4 --depth 5 --fov 60 "
              "--camera-pos 0,0,0 --camera-target 0,0,-1 --camera-up 0,1,0");

    const Options shown = parse({"a.scene",    "--depth",         "2",           "--fov",
                                 "33.3",       "--background",    "0.1,0.2,0.3", "--sampler",
                                 "stratified", "--seed",          "7",           "--precision",
                                 "fp64",       "--sphere-test",   "naive",       "--triangle-test",
                                 "mt",         "--offset",        "fixed",       "--camera-pos",
                                 "1,2,3",      "--camera-target", "0.1,0,-1",    "--accel",
                                 "none",       "--device",        "1",           "--no-cache"});
    const std::string command = headlessCommand(shown, shown.camera, 64, 48, 4);
    EXPECT_EQ(
        command,
        "Raytracer a.scene -o OUT.png --width 64 --height 48 --spp 4 --depth 2 "
        "--fov 33.299999999999997 --camera-pos 1,2,3 --camera-target 0.10000000000000001,0,-1 "
        "--camera-up 0,1,0 --background "
        "0.10000000000000001,0.20000000000000001,0.29999999999999999 --sampler "
        "stratified --seed 7 --precision fp64 --sphere-test naive --triangle-test mt "
        "--offset fixed");
    const Options again = parse(shellWords(command));
    EXPECT_EQ(again.outputPath, "OUT.png");
    EXPECT_EQ(again.width, 64u);
    EXPECT_EQ(again.height, 48u);
    EXPECT_EQ(again.samplesPerPixel, 4u);
    EXPECT_EQ(again.depth, 2u);
    EXPECT_EQ(again.fovDegrees, shown.fovDegrees);
    EXPECT_EQ(again.background, shown.background);
    EXPECT_TRUE(again.camera == shown.camera);
    EXPECT_TRUE(again.kernel == shown.kernel);
}

TEST(ScreenshotCommand, QuotesTheSceneAndShaderFolder) {
    Options options =
        parse({"my scene.scene", "--shader-dir", shaderFolder("my shaders").string()});
    const std::string command = headlessCommand(options, options.camera, 8, 8, 1);
    const Options again = parse(shellWords(command));
    EXPECT_EQ(again.scenePath, options.scenePath);
    EXPECT_EQ(again.shaderDirectory, options.shaderDirectory);
}

} // namespace

namespace {

// parse's UsageError message, or "" when words parse.
std::string usageErrorOf(const std::vector<std::string>& words) {
    try {
        parse(words);
    } catch (const UsageError& error) {
        return error.what();
    }
    return "";
}

} // namespace

TEST(CommandLine, OptionEqualsValueIsTheSameAsTwoWords) {
    const std::vector<std::pair<std::string, std::string>> pairs = {{"--width", "800"},
                                                                    {"--height", "16"},
                                                                    {"--offset", "scaled"},
                                                                    {"--spp", "4"},
                                                                    {"--sampler", "grid"},
                                                                    {"--fov", "35.5"},
                                                                    {"--camera-pos", "1,2,3"},
                                                                    {"--background", "0,0.5,1"},
                                                                    {"--accel", "none"},
                                                                    {"--output", "o.pfm"},
                                                                    {"--seed", "7"},
                                                                    {"--depth", "0"},
                                                                    {"--precision", "fp64"},
                                                                    {"--pixel", "3,4"},
                                                                    {"--device", "a=b"},
                                                                    {"--triangle-test", "mt"},
                                                                    {"--sphere-test", "naive"},
                                                                    {"--threads", "2"}};
    for (const auto& [flag, text] : pairs) {
        const Options joined = parse({"x.scene", flag + "=" + text});
        EXPECT_EQ(joined, parse({"x.scene", flag, text})) << flag << "=" << text;
        EXPECT_NE(joined, parse({"x.scene"})) << flag << "=" << text << " changed nothing";
    }
    // Only the first '=' splits: the rest belongs to the value.
    EXPECT_EQ(parse({"x.scene", "--device=a=b"}).device, "a=b");
    // The value after '=' is checked as the separate word is.
    EXPECT_EQ(usageErrorOf({"x.scene", "--width="}),
              "--width expects a whole number from 1 to 65536, got ''");
    EXPECT_EQ(usageErrorOf({"x.scene", "--offset=far"}),
              "--offset expects fixed, scaled or error-bound, got 'far'");
}

TEST(CommandLine, SnapshotsAreIncreasingCountsUpToTheWindowsTarget) {
    EXPECT_EQ(parse({"x.scene", "--spp", "256", "--snapshots", "1,16,256"}).snapshotCounts,
              (std::vector<std::uint32_t>{1, 16, 256}));
    const std::string expects = "--snapshots expects sample counts K,K,... (up to 64 whole "
                                "numbers from 1, increasing), got '";
    for (const char* counts : {"5,3", "4,4", "0", "a", "1,,2", ""})
        EXPECT_EQ(usageErrorOf({"x.scene", "--spp", "8", "--snapshots", counts}),
                  expects + counts + "'")
            << counts;
    EXPECT_EQ(usageErrorOf({"x.scene", "--snapshots", "4"}),
              "--snapshots needs --spp N, the samples per pixel the window refines to");
    EXPECT_EQ(usageErrorOf({"x.scene", "--spp", "8", "--snapshots", "2,9"}),
              "--snapshots 9 lies beyond --spp 8, where the window stops refining");
    for (const std::vector<std::string>& headless : {std::vector<std::string>{"-o", "x.png"},
                                                     {"--bench", "2"},
                                                     {"--pixel", "1,1"},
                                                     {"--check"}})
        EXPECT_EQ(
            usageErrorOf([&] {
                std::vector<std::string> words = {"x.scene", "--spp", "8", "--snapshots", "2"};
                words.insert(words.end(), headless.begin(), headless.end());
                return words;
            }()),
            "--snapshots writes the window's screenshots and cannot be combined with -o, "
            "--bench, --bench-window, --pixel or --check")
            << headless[0];
}

TEST(CommandLine, SwitchGivenAValueIsAUsageError) {
    for (const char* flag : {"--help", "--version", "--validate", "--no-cache", "--progress",
                             "--window", "--quiet", "--list-devices"})
        EXPECT_EQ(usageErrorOf({"x.scene", std::string(flag) + "=yes"}),
                  std::string(flag) + " takes no value, got '" + flag + "=yes'");
    EXPECT_EQ(usageErrorOf({"x.scene", "--frobnicate=3"}), "unknown option '--frobnicate'");
}

TEST(CommandLine, UnknownOptionNamesTheNearMisses) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--widht", "; did you mean --width?"},    // two letters swapped: distance 2
        {"--wdth", "; did you mean --width?"},     // one left out
        {"--thread", "; did you mean --threads?"}, // the plural forgotten
        {"--Width", "; did you mean --width?"},    // case
        {"--accell", "; did you mean --accel?"},
        {"--camera", "; did you mean --camera-path, --camera-pos or --camera-target?"}, // prefix
        {"--dump", "; did you mean --dump-shaders?"},
        {"--frobnicate", ""}, // nothing close
        {"--x", ""},          // too short to mean one
        {"-x", ""},
        {"--general-kernl", ""}, // hidden options are not suggested
    };
    for (const auto& [typed, hint] : cases)
        EXPECT_EQ(usageErrorOf({"x.scene", typed}), "unknown option '" + typed + "'" + hint);
}

// Every suggestion is an option that parseOptions accepts: the list comes from --help.
TEST(CommandLine, SuggestedOptionsAreRealOptions) {
    const std::vector<std::string> options = documentedOptions(usageText());
    EXPECT_GE(options.size(), 29u); // every one --help listed when this was written
    for (const std::string& option : options) {
        const std::string error = usageErrorOf({"x.scene", option, "1"});
        EXPECT_EQ(error.find("unknown option"), std::string::npos) << option << ": " << error;
    }
}

TEST(CommandLine, OutputOptionsAreChecked) {
    EXPECT_EQ(parse({"x.scene", "-o", "a.jpg"}).jpegQuality, 90u);
    EXPECT_EQ(parse({"x.scene", "-o", "a.jpeg", "--quality", "35"}).jpegQuality, 35u);
    EXPECT_EQ(parse({"x.scene", "--output=-"}).outputPath, "-");
    EXPECT_TRUE(parse({"--list-devices"}).listDevices); // no scene needed
    EXPECT_EQ(usageErrorOf({"x.scene", "-o", "a.gif"}),
              "-o a.gif: the output must be a file name ending in .png, .jpg, .jpeg, .ppm, .pfm "
              "or .exr, or - for a PNG on stdout");
    EXPECT_EQ(usageErrorOf({"x.scene", "-o", "a.ppm", "--quality", "90"}),
              "--quality sets a JPEG's quality and needs -o FILE.jpg or FILE.jpeg, got -o a.ppm");
    EXPECT_EQ(usageErrorOf({"x.scene", "--quality", "50", "-o", "a.JPG"}), "");
    EXPECT_EQ(usageErrorOf({"x.scene", "-o", "-", "--pixel", "0,0"}),
              "-o - writes the PNG to stdout and cannot be combined with --pixel or --bench, "
              "which print JSON there");
}

TEST(OutputPattern, FieldsAreReplaced) {
    EXPECT_EQ(expandOutputPattern("out/{name}-{frame}.png", "table", 7), "out/table-7.png");
    EXPECT_EQ(expandOutputPattern("f-{frame:04}.png", "x", 7), "f-0007.png");
    EXPECT_EQ(expandOutputPattern("f-{frame:02}.png", "x", 12345), "f-12345.png");
    EXPECT_EQ(expandOutputPattern("{name}/{name}.exr", "a b", 0), "a b/a b.exr");
    EXPECT_EQ(expandOutputPattern("plain.png", "x", 3), "plain.png");
    EXPECT_TRUE(outputPatternHas("a{frame:09}.png", "frame"));
    EXPECT_FALSE(outputPatternHas("a{frame:09}.png", "name"));
    EXPECT_EQ(outputPatternProblem("a{name.png"), "a '{' is not closed");
    EXPECT_EQ(outputPatternProblem("a{frame:0}.png"),
              "unknown field {frame:0} (known: {name}, {frame}, {frame:04})");
    EXPECT_EQ(outputPatternProblem("a{}.png"),
              "unknown field {} (known: {name}, {frame}, {frame:04})");
}

TEST(OutputPattern, AFolderStandsForNamePng) {
    EXPECT_EQ(parse({"a.scene", "b.scene", "-o", "out/"}).outputPath, "out/{name}.png");
    EXPECT_EQ(parse({"a.scene", "-o", "out/", "--turntable", "3"}).outputPath,
              "out/{name}-{frame:04}.png");
    const std::filesystem::path existing = std::filesystem::path(TEST_OUTPUT_DIR) / "command-line";
    std::filesystem::create_directories(existing);
    EXPECT_EQ(parse({"a.scene", "b.scene", "-o", existing.string()}).outputPath,
              existing / "{name}.png");
    // For one image an existing folder is not taken for one: a file name was meant.
    try {
        parse({"a.scene", "-o", existing.string()});
        ADD_FAILURE() << "no usage error";
    } catch (const UsageError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "-o " + existing.string() +
                      ": the output must be a file name ending in .png, .jpg, .jpeg, .ppm, .pfm or "
                      ".exr, or - for a PNG on stdout");
    }
    EXPECT_EQ(parse({"a.scene", "-o", existing.string() + "/"}).outputPath,
              existing.string() + "/{name}.png");
}
