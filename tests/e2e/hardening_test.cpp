// Hardening: device limits named up front, environment faults (no driver, no
// display, a lost device), nothing lost (unwritable output fails before rendering, a
// failed or interrupted run leaves an existing PNG as it was), Ctrl-C ends a long
// render cleanly. Unit tests where a real fault cannot be provoked on lavapipe.
#include "gpu/image_limits.h"
#include "gpu/vk_check.h"
#include "render/interrupt.h"
#include "render/scene_upload.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

namespace {

using Clock = std::chrono::steady_clock;

std::string minimalScene() {
    return "1\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -3\nrad: 1\ndif: 0.5 0.2 0.2\nspe: 0.3 0.3 0.3\n"
           "shi: 10\n";
}

std::filesystem::path writeScene(const std::filesystem::path& dir) {
    std::filesystem::path path = dir / "input.scene";
    writeTextFile(path, minimalScene());
    return path;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// An existing "good" PNG that a failed or interrupted run must leave as it was.
std::string writeGoodPng(const std::filesystem::path& path) {
    Image8 image;
    image.width = image.height = 4;
    image.rgba.assign(4 * 4 * 4, 200);
    writePng(path, image);
    return readWholeFile(path);
}

// Sets an environment variable for one scope.
struct ScopedEnvironment {
    ScopedEnvironment(const char* variableName, const char* value) : name(variableName) {
        if (const char* old = std::getenv(name)) saved = old, hadValue = true;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnvironment() {
        if (hadValue)
            setenv(name, saved.c_str(), 1);
        else
            unsetenv(name);
    }
    const char* name;
    std::string saved;
    bool hadValue = false;
};

ImageLimits lavapipeLikeLimits() {
    ImageLimits limits;
    limits.deviceName = "Test GPU";
    limits.maxImageDimension2D = 16384;
    limits.maxMemoryAllocationSize = VkDeviceSize(2) << 30;
    limits.largestDeviceLocalHeap = VkDeviceSize(8) << 30;
    limits.largestHostVisibleHeap = VkDeviceSize(8) << 30;
    return limits;
}

void expectThrowsWith(const std::function<void()>& action, const std::vector<std::string>& parts) {
    try {
        action();
        ADD_FAILURE() << "no exception; expected one naming " << parts.front();
    } catch (const std::runtime_error& error) {
        for (const std::string& part : parts)
            EXPECT_TRUE(contains(error.what(), part)) << error.what();
    }
}

TEST(Limits, ImagesWithinTheDeviceLimitsFit) {
    EXPECT_NO_THROW(checkImageFits(lavapipeLikeLimits(), 16384, 16384, true));
    EXPECT_NO_THROW(checkImageFits(lavapipeLikeLimits(), 1, 1, true));
}

TEST(Limits, EachExceededLimitIsNamedWithTheDevice) {
    ImageLimits limits = lavapipeLikeLimits();
    expectThrowsWith(
        [&] { checkImageFits(limits, 16385, 16, true); },
        {"16385x16 image exceeds this device's maxImageDimension2D of 16384", "(Test GPU)"});
    limits.maxMemoryAllocationSize = VkDeviceSize(512) << 20;
    expectThrowsWith([&] { checkImageFits(limits, 16384, 16384, true); },
                     {"needs 1024 MiB", "maxMemoryAllocationSize of 512 MiB (Test GPU)"});
    limits = lavapipeLikeLimits();
    limits.largestDeviceLocalHeap = VkDeviceSize(256) << 20;
    expectThrowsWith([&] { checkImageFits(limits, 16384, 16384, true); },
                     {"largest device-local memory heap of 256 MiB (Test GPU)"});
    limits = lavapipeLikeLimits();
    limits.largestHostVisibleHeap = VkDeviceSize(256) << 20;
    expectThrowsWith([&] { checkImageFits(limits, 16384, 16384, true); },
                     {"largest host-visible heap of 256 MiB (Test GPU)"});
    EXPECT_NO_THROW(checkImageFits(limits, 16384, 16384, false)); // the window reads nothing back
}

TEST(Limits, ASceneBeyondMaxStorageBufferRangeNamesTheLimitAndTheDevice) {
    // uploadScene checks every array against the limit before it touches the device,
    // so a device with a tiny limit stands in for a 128 MiB scene on lavapipe.
    Context context;
    context.properties.limits.maxStorageBufferRange = 1024;
    context.properties.limits.minStorageBufferOffsetAlignment = 16;
    std::snprintf(context.properties.deviceName, sizeof(context.properties.deviceName), "Test GPU");
    Scene scene;
    scene.spheres.resize(100); // 1600 bytes of spheres
    expectThrowsWith([&] { uploadScene(context, packSceneInFileOrder(scene)); },
                     {"spheres take 1600 bytes", "maxStorageBufferRange of 1024 bytes (Test GPU)"});
}

TEST(Limits, ExtremeImageShapesRender) {
    std::filesystem::path dir = freshOutputDir("hardening/shapes");
    std::filesystem::path scene = writeScene(dir);
    for (auto [width, height] :
         {std::pair{"16384", "4"}, std::pair{"4", "16384"}, std::pair{"1", "1"}}) {
        ProcessResult run = runRaytracer({scene.string(), "-o", (dir / "out.png").string(),
                                          "--width", width, "--height", height, "--validate"});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        Image8 image = readPng(dir / "out.png");
        EXPECT_EQ(std::to_string(image.width) + "x" + std::to_string(image.height),
                  std::string(width) + "x" + height);
    }
}

TEST(Limits, AbsurdSizesSamplesAndDepthsAreUsageErrors) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"x.scene", "--width", "65537"},
         "--width expects a whole number from 1 to 65536, got '65537'"},
        {{"x.scene", "--height", "0"}, "--height expects a whole number from 1 to 65536, got '0'"},
        {{"x.scene", "--width", "99999999999999999999"},
         "--width expects a whole number from 1 to 65536, got '99999999999999999999'"},
        {{"x.scene", "--width", "4294967296"},
         "--width expects a whole number from 1 to 65536, got '4294967296'"},
        {{"x.scene", "--width", "64.5"},
         "--width expects a whole number from 1 to 65536, got '64.5'"},
        {{"x.scene", "--width", ""}, "--width expects a whole number from 1 to 65536, got ''"},
        {{"x.scene", "--spp", "0"}, "--spp expects a whole number from 1 to 65536, got '0'"},
        {{"x.scene", "--spp", "65537"},
         "--spp expects a whole number from 1 to 65536, got '65537'"},
        {{"x.scene", "--spp", "-1"}, "--spp expects a whole number from 1 to 65536, got '-1'"},
        {{"x.scene", "--depth", "-1"}, "--depth expects a whole number from 0 to 64, got '-1'"},
        {{"x.scene", "--depth", "1000000"},
         "--depth expects a whole number from 0 to 64, got '1000000'"},
        {{"x.scene", "--bench", "0"}, "--bench expects a whole number from 1 to 100000, got '0'"},
        {{"x.scene", "--fov", "nan"}, "--fov expects a number, got 'nan'"},
        {{"x.scene", "--fov", "-10"}, "--fov expects degrees strictly between 0 and 180"},
        {{"x.scene", "--background", "1,-1,1"},
         "--background expects three non-negative numbers R,G,B"},
        {{"x.scene", "--window", "-o", "x.png"}, "--window cannot be combined with -o or --bench"},
    };
    for (const auto& [args, message] : cases) {
        ProcessResult run = runRaytracer(args);
        EXPECT_EQ(run.exitCode, 2) << message << "\n" << run.err;
        EXPECT_TRUE(contains(run.err, "error: " + message)) << run.err;
    }
}

TEST(EnvironmentFaults, NoVulkanDriverIsAClearErrorNotACrash) {
    std::filesystem::path dir = freshOutputDir("hardening/no-driver");
    std::filesystem::path scene = writeScene(dir);
    const std::string missing = (dir / "no-such-icd.json").string();
    ScopedEnvironment icd("VK_ICD_FILENAMES", missing.c_str());
    ScopedEnvironment driver("VK_DRIVER_FILES", missing.c_str());
    ProcessResult run = runRaytracer({scene.string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_TRUE(contains(run.err, "error: no Vulkan driver found")) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png.tmp"));
}

// Without a driver the loader fails any instance; --version makes none, so it answers as it
// does with one (cli_test checks those lines).
TEST(EnvironmentFaults, VersionNeedsNoVulkanDriver) {
    const std::string withDriver = runRaytracer({"--version"}).out;
    std::filesystem::path dir = freshOutputDir("hardening/version-no-driver");
    const std::string missing = (dir / "no-such-icd.json").string();
    ScopedEnvironment icd("VK_ICD_FILENAMES", missing.c_str());
    ScopedEnvironment driver("VK_DRIVER_FILES", missing.c_str());
    ProcessResult run = runRaytracer({"--version"});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out.rfind("Raytracer " RAYTRACER_VERSION "\n", 0), 0u) << run.out;
    EXPECT_EQ(run.out, withDriver);
    EXPECT_EQ(run.err, "");
}

// --check makes no instance either: a valid scene passes and a malformed one fails, with
// no driver visible, exactly as they do with one.
TEST(EnvironmentFaults, CheckNeedsNoVulkanDriver) {
    std::filesystem::path dir = freshOutputDir("hardening/check-no-driver");
    const std::filesystem::path valid = writeScene(dir);
    const std::filesystem::path malformed = dir / "malformed.scene";
    writeTextFile(malformed, "1\namb: 0.1 0.1 0.1\nsphere\npos: 0 0\n");
    const ProcessResult validWithDriver = runRaytracer({valid.string(), "--check"});
    const ProcessResult malformedWithDriver = runRaytracer({malformed.string(), "--check"});
    const std::string missing = (dir / "no-such-icd.json").string();
    ScopedEnvironment icd("VK_ICD_FILENAMES", missing.c_str());
    ScopedEnvironment driver("VK_DRIVER_FILES", missing.c_str());
    const ProcessResult validRun = runRaytracer({valid.string(), "--check"});
    EXPECT_EQ(validRun.exitCode, 0) << validRun.err;
    EXPECT_TRUE(contains(validRun.out, ": valid\nspheres: ")) << validRun.out;
    EXPECT_EQ(validRun.out, validWithDriver.out);
    EXPECT_EQ(validRun.err, validWithDriver.err);
    const ProcessResult malformedRun = runRaytracer({malformed.string(), "--check"});
    EXPECT_EQ(malformedRun.exitCode, 3) << malformedRun.err;
    EXPECT_TRUE(contains(malformedRun.err, malformed.string() + ":")) << malformedRun.err;
    EXPECT_EQ(malformedRun.err, malformedWithDriver.err);
}

TEST(EnvironmentFaults, WindowAskedForWithoutADisplayIsAnError) {
    std::filesystem::path dir = freshOutputDir("hardening/window");
    std::filesystem::path scene = writeScene(dir);
    ScopedEnvironment display("DISPLAY", nullptr);
    ScopedEnvironment wayland("WAYLAND_DISPLAY", nullptr);
    ProcessResult run =
        runRaytracer({scene.string(), "--window", "--width", "32", "--height", "24"}, 120, dir);
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_TRUE(contains(run.err, "error: --window was given, but no window can be opened: "))
        << run.err;
    EXPECT_TRUE(contains(run.err, "DISPLAY")) << run.err; // GLFW's reason
    EXPECT_FALSE(std::filesystem::exists(dir / "input.png"))
        << "no headless fallback with --window";
}

TEST(EnvironmentFaults, ALostDeviceSaysSo) {
    // lavapipe cannot be made to lose its device; the one error path for every Vulkan
    // call is what a lost device goes through.
    try {
        throwVulkanError(VK_ERROR_DEVICE_LOST, "vkWaitForFences(...)",
                         "/src/host/render/headless.cpp", 42);
        FAIL() << "no exception";
    } catch (const VulkanError& error) {
        EXPECT_EQ(error.result, VK_ERROR_DEVICE_LOST);
        EXPECT_EQ(std::string(error.what()),
                  "Vulkan call failed with VK_ERROR_DEVICE_LOST (-4) at headless.cpp:42: "
                  "vkWaitForFences(...)\n"
                  "(the device was lost: a driver crash, a GPU reset or a watchdog timeout)");
    }
}

TEST(NothingLost, UnwritableOutputFailsBeforeRenderingAndWritesNothing) {
    std::filesystem::path dir = freshOutputDir("hardening/unwritable");
    std::filesystem::path scene = writeScene(dir);
    writeTextFile(dir / "a-file", "not a folder");
    std::filesystem::create_directories(dir / "folder.png");
    const std::vector<std::pair<std::filesystem::path, std::string>> cases = {
        {dir / "no-such-folder" / "out.png",
         "the folder " + (dir / "no-such-folder").string() + " does not exist\n"},
        {dir / "a-file" / "out.png", "out.png.tmp: Not a directory"},
        {"/proc/raytracer-out.png",
         "cannot create /proc/raytracer-out.png.tmp"}, // unwritable, even for root
        {dir / "folder.png", "folder.png: is a folder, not a file name"},
    };
    for (const auto& [output, message] : cases) {
        ProcessResult run = runRaytracer({scene.string(), "-o", output.string()});
        EXPECT_EQ(run.exitCode, 1) << run.err;
        EXPECT_TRUE(contains(run.err, "error: " + output.string() + ": ")) << run.err;
        EXPECT_TRUE(contains(run.err, message)) << run.err;
        EXPECT_FALSE(contains(run.err, "Device:"))
            << "failed only after choosing a device: " << run.err;
        EXPECT_FALSE(std::filesystem::exists(output.string() + ".tmp"));
    }
    if (geteuid() != 0) { // root writes into read-only folders
        std::filesystem::create_directories(dir / "read-only");
        std::filesystem::permissions(dir / "read-only", std::filesystem::perms::owner_read |
                                                            std::filesystem::perms::owner_exec);
        ProcessResult run =
            runRaytracer({scene.string(), "-o", (dir / "read-only" / "out.png").string()});
        EXPECT_EQ(run.exitCode, 1) << run.err;
        EXPECT_TRUE(contains(run.err, "Permission denied")) << run.err;
        std::filesystem::permissions(dir / "read-only", std::filesystem::perms::owner_all);
    }
}

TEST(NothingLost, AFailedRunLeavesAnExistingPngAsItWas) {
    std::filesystem::path dir = freshOutputDir("hardening/keep");
    std::filesystem::path scene = writeScene(dir);
    const std::filesystem::path output = dir / "out.png";
    const std::string good = writeGoodPng(output);

    // The temporary name is taken by a folder: nothing can be written, found up front.
    std::filesystem::create_directories(dir / "out.png.tmp");
    ProcessResult blocked = runRaytracer({scene.string(), "-o", output.string()});
    EXPECT_EQ(blocked.exitCode, 1) << blocked.err;
    EXPECT_TRUE(contains(blocked.err, "cannot create " + output.string() + ".tmp")) << blocked.err;
    EXPECT_EQ(readWholeFile(output), good);
    std::filesystem::remove(dir / "out.png.tmp");

    // A failure after the output was reserved (no such device) removes the reservation.
    ProcessResult noDevice =
        runRaytracer({scene.string(), "-o", output.string(), "--device", "no-such-gpu"});
    EXPECT_EQ(noDevice.exitCode, 1) << noDevice.err;
    EXPECT_EQ(readWholeFile(output), good);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png.tmp"));

    // And a good run replaces it.
    ProcessResult ok =
        runRaytracer({scene.string(), "-o", output.string(), "--width", "8", "--height", "8"});
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_EQ(readPng(output).width, 8);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png.tmp"));
}

TEST(NothingLost, TheInterruptFlagIsRaisedBySigintAndSigterm) {
    installInterruptHandlers();
    EXPECT_EQ(interruptSignal(), 0);
    EXPECT_NO_THROW(throwIfInterrupted());
    std::raise(SIGTERM);
    EXPECT_EQ(interruptSignal(), SIGTERM);
    try {
        throwIfInterrupted();
        FAIL() << "no exception";
    } catch (const Interrupted& interruption) {
        EXPECT_EQ(interruption.signalNumber, SIGTERM);
        EXPECT_TRUE(contains(interruption.what(), "interrupted by SIGTERM")) << interruption.what();
    }
}

// A long render (minutes on lavapipe) gets a signal once it is under way: it must end
// before the frame is done, with 128 + the signal, a note, no PNG and no .tmp, and the PNG
// that was there before untouched.
void expectSignalEndsALongRenderCleanly(int signalNumber, const std::string& name) {
    std::filesystem::path dir = freshOutputDir("hardening/interrupt-" + name);
    const std::filesystem::path output = dir / "out.png";
    const std::string good = writeGoodPng(output);
    Clock::time_point sent;
    bool signalled = false;
    ProcessResult run = runRaytracerWhile(
        {std::string(PROJECT_SCENES_DIR) + "/mesh.scene", "-o", output.string(), "--width", "4096",
         "--height", "4096", "--spp", "16"},
        [&](pid_t pid, const std::filesystem::path& errPath) {
            // Wait until the device is chosen (the handlers are installed by then), then
            // a little longer, so that submissions are running.
            waitForText(errPath, "Device:");
            std::this_thread::sleep_for(std::chrono::seconds(1));
            sent = Clock::now();
            signalled = kill(pid, signalNumber) == 0;
        },
        300);
    const double secondsToExit = std::chrono::duration<double>(Clock::now() - sent).count();
    ASSERT_TRUE(signalled);
    EXPECT_EQ(run.exitCode, 128 + signalNumber) << run.err;
    EXPECT_TRUE(contains(run.err, "note: interrupted by " + name)) << run.err;
    // It stopped before the frame was done (no summary line), however long a submission
    // takes on this machine: how soon is for the benchmarks to say, not a test.
    EXPECT_FALSE(contains(run.err, "Rendered ")) << "the render ran to its end: " << run.err;
    EXPECT_EQ(readWholeFile(output), good) << "the existing PNG was changed";
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png.tmp"));
    std::printf("%s: exited %.2f s after the signal\n", name.c_str(), secondsToExit);
}

TEST(NothingLost, CtrlCEndsALongRenderCleanly) {
    expectSignalEndsALongRenderCleanly(SIGINT, "SIGINT");
}

TEST(NothingLost, SigtermEndsALongRenderCleanly) {
    expectSignalEndsALongRenderCleanly(SIGTERM, "SIGTERM");
}

} // namespace
