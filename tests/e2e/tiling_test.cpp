// Headless frames traced in many short submissions (host/render/region_planner.h): the regions
// cover every pixel exactly once and adapt toward the target time; any tiling gives
// the same bytes; a long render reports progress (in place on a terminal, one summary
// line elsewhere).
#include "test_support.h"

#include "render/region_planner.h"
#include "shared.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <functional>
#include <iterator>
#include <pty.h>
#include <regex>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const fs::path kShowcase = fs::path(PROJECT_SCENES_DIR) / "showcase.scene";

// Drives a planner over a whole frame, answering each region with millisecondsFor,
// and checks that the regions tile the image: every pixel once, whole workgroups
// except at the right and bottom edges. Returns the regions.
std::vector<TraceRegion>
planFrame(RegionPlanner& planner, std::uint32_t width, std::uint32_t height,
          const std::function<double(const TraceRegion&)>& millisecondsFor) {
    std::vector<std::uint8_t> covered(std::size_t(width) * height, 0);
    std::size_t coveredPixels = 0;
    std::vector<TraceRegion> regions;
    beginFrame(planner, width, height);
    TraceRegion region;
    while (nextRegion(planner, region)) {
        EXPECT_GT(region.width, 0u);
        EXPECT_GT(region.height, 0u);
        EXPECT_LE(region.x + region.width, width);
        EXPECT_LE(region.y + region.height, height);
        EXPECT_EQ(region.x % WORKGROUP_SIZE_X, 0u);
        EXPECT_EQ(region.y % WORKGROUP_SIZE_Y, 0u);
        if (region.x + region.width < width) {
            EXPECT_EQ(region.width % WORKGROUP_SIZE_X, 0u);
        }
        if (region.y + region.height < height) {
            EXPECT_EQ(region.height % WORKGROUP_SIZE_Y, 0u);
        }
        for (std::uint32_t y = region.y; y < region.y + region.height && y < height; ++y)
            for (std::uint32_t x = region.x; x < region.x + region.width && x < width; ++x)
                coveredPixels += covered[std::size_t(y) * width + x]++ == 0;
        regions.push_back(region);
        EXPECT_EQ(frameCovered(planner), coveredPixels == covered.size());
        regionTraced(planner, region, millisecondsFor(region));
        if (regions.size() > 1000000) break;
    }
    EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](std::uint8_t n) { return n == 1; }))
        << width << "x" << height << ": a pixel traced twice or never";
    return regions;
}

double pixelsOf(const TraceRegion& region) {
    return double(region.width) * region.height;
}

TEST(RegionPlanner, RegionsCoverEveryPixelOnceWhateverTheTimes) {
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> sizes = {
        {1, 1}, {7, 5}, {9, 17}, {640, 480}, {1500, 1100}, {4000, 3}, {3, 4000}};
    const std::vector<std::function<double(const TraceRegion&)>> timings = {
        [](const TraceRegion&) { return 0.001; },                    // instant
        [](const TraceRegion&) { return 900.0; },                    // always too slow
        [](const TraceRegion& r) { return pixelsOf(r) / 2000.0; },   // 2000 pixels per ms
        [](const TraceRegion& r) { return r.y > 300 ? 50.0 : 0.5; }, // expensive lower half
    };
    for (auto [width, height] : sizes)
        for (const auto& timing : timings)
            for (std::uint32_t fixedSide : {0u, 8u, 64u, 20u}) {
                RegionPlanner planner = createRegionPlanner(fixedSide);
                planFrame(planner, width, height, timing);
            }
}

TEST(RegionPlanner, AdaptsTowardTheTargetAndGrowsGradually) {
    const double pixelsPerMs = 5000.0;
    RegionPlanner planner = createRegionPlanner(0);
    std::vector<double> budgets; // the budget each region was cut from
    std::vector<TraceRegion> regions = planFrame(planner, 4096, 4096, [&](const TraceRegion& r) {
        budgets.push_back(planner.budgetPixels);
        return pixelsOf(r) / pixelsPerMs;
    });
    ASSERT_GT(regions.size(), 10u);
    EXPECT_EQ(pixelsOf(regions[0]), 64.0 * 64.0)
        << "the first region is small: it pays for the compile";
    for (std::size_t i = 0; i < regions.size(); ++i) {
        if (i > 0) {
            EXPECT_LE(budgets[i], 4.0 * budgets[i - 1]) << "region " << i;
        }
        // The rest of a strip is taken rather than a sliver left, so a region may be
        // half as large again as its budget (and at least one workgroup wide).
        EXPECT_LE(pixelsOf(regions[i]),
                  1.5 * budgets[i] + double(WORKGROUP_SIZE_X) * regions[i].height)
            << "region " << i;
    }
    // Once learned, a typical region takes about kTargetSubmissionMs.
    std::vector<double> times;
    for (const TraceRegion& region : regions)
        times.push_back(pixelsOf(region) / pixelsPerMs);
    std::sort(times.begin(), times.end());
    EXPECT_NEAR(times[times.size() / 2], kTargetSubmissionMs, kTargetSubmissionMs * 0.3);
    EXPECT_LT(times.back(), 2.0 * kTargetSubmissionMs);

    // The next frame starts from what was learned.
    beginFrame(planner, 4096, 4096);
    TraceRegion first;
    ASSERT_TRUE(nextRegion(planner, first));
    EXPECT_GT(pixelsOf(first), 64.0 * 64.0 * 16);
}

// A CPU device gets longer submissions (no watchdog; each submission costs lavapipe an
// idle tail): the same adapting, toward kCpuTargetSubmissionMs, in fewer submissions.
TEST(RegionPlanner, CpuTargetAdaptsTowardItsOwnTarget) {
    const double pixelsPerMs = 5000.0;
    const auto timing = [&](const TraceRegion& r) { return pixelsOf(r) / pixelsPerMs; };
    RegionPlanner gpu = createRegionPlanner(0);
    RegionPlanner cpu = createRegionPlanner(0, kCpuTargetSubmissionMs);
    planFrame(gpu, 4096, 4096, timing); // both learn on a first frame
    planFrame(cpu, 4096, 4096, timing);
    std::vector<TraceRegion> gpuRegions = planFrame(gpu, 4096, 4096, timing);
    std::vector<TraceRegion> cpuRegions = planFrame(cpu, 4096, 4096, timing);
    std::vector<double> times;
    for (const TraceRegion& region : cpuRegions)
        times.push_back(timing(region));
    std::sort(times.begin(), times.end());
    EXPECT_NEAR(times[times.size() / 2], kCpuTargetSubmissionMs, kCpuTargetSubmissionMs * 0.3);
    EXPECT_LT(times.back(), 2.0 * kCpuTargetSubmissionMs);
    EXPECT_LT(cpuRegions.size() * 4, gpuRegions.size());
    EXPECT_GT(kCpuTargetSubmissionMs, kTargetSubmissionMs);
    EXPECT_LE(kCpuTargetSubmissionMs, 500.0) << "Ctrl-C and progress must stay responsive";
}

TEST(RegionPlanner, SlowRegionsShrinkToOneWorkgroup) {
    RegionPlanner planner = createRegionPlanner(0);
    std::vector<TraceRegion> regions =
        planFrame(planner, 256, 256, [](const TraceRegion&) { return 1000.0; });
    EXPECT_EQ(pixelsOf(regions.back()), double(WORKGROUP_SIZE_X) * WORKGROUP_SIZE_Y);
}

TEST(RegionPlanner, FixedSideIsWholeWorkgroups) {
    RegionPlanner planner = createRegionPlanner(64);
    auto regions = planFrame(planner, 1500, 1100, [](const TraceRegion&) { return 1.0; });
    EXPECT_EQ(regions.size(), 24u * 18u);
    RegionPlanner odd = createRegionPlanner(20);
    regions = planFrame(odd, 100, 100, [](const TraceRegion&) { return 1.0; });
    EXPECT_EQ(regions[0].width, 24u);
    EXPECT_EQ(regions[0].height, 24u);
}

// "Rendered WxH in S s: N submissions, ..." -> N, or -1 without that line.
long submissionsIn(const std::string& err) {
    std::size_t at = err.find("Rendered ");
    if (at == std::string::npos) return -1;
    std::size_t colon = err.find(": ", at);
    if (colon == std::string::npos) return -1;
    return std::strtol(err.c_str() + colon + 2, nullptr, 10);
}

TEST(Tiling, LargeImageIsTheSameWithSmallTilesAndReportsProgress) {
    fs::path dir = freshOutputDir("tiling/large");
    const std::vector<std::string> common = {
        kShowcase.string(), "--width", "1500", "--height", "1100", "--progress", "--no-cache"};
    std::vector<std::string> adaptive = common, small = common;
    adaptive.insert(adaptive.end(), {"-o", (dir / "adaptive.png").string()});
    small.insert(small.end(),
                 {"-o", (dir / "small.png").string(), "--region-size", "64", "--validate"});

    ProcessResult adaptiveRun = runRaytracer(adaptive);
    ASSERT_EQ(adaptiveRun.exitCode, 0) << adaptiveRun.err;
    ProcessResult smallRun = runRaytracer(small);
    ASSERT_EQ(smallRun.exitCode, 0) << smallRun.err;
    EXPECT_FALSE(hasValidationMessage(smallRun)) << smallRun.err;
    EXPECT_EQ(readWholeFile(dir / "adaptive.png"), readWholeFile(dir / "small.png"));

    // stderr is a file here, not a terminal: one summary line, no carriage returns.
    EXPECT_NE(smallRun.err.find("Rendered 1500x1100 in "), std::string::npos) << smallRun.err;
    EXPECT_EQ(submissionsIn(smallRun.err), 24 * 18) << smallRun.err;
    EXPECT_EQ(smallRun.err.find('\r'), std::string::npos) << smallRun.err;
    EXPECT_GT(submissionsIn(adaptiveRun.err), 1)
        << "a large frame is split into several submissions on lavapipe: " << adaptiveRun.err;
}

TEST(Tiling, SamplesPerPixelAreTheSameWithSmallTiles) {
    fs::path dir = freshOutputDir("tiling/spp");
    const std::vector<std::string> common = {
        kShowcase.string(), "--width", "200", "--height", "150", "--spp", "4", "--no-cache"};
    std::vector<std::string> adaptive = common, small = common;
    adaptive.insert(adaptive.end(), {"-o", (dir / "adaptive.png").string()});
    small.insert(small.end(), {"-o", (dir / "small.png").string(), "--region-size", "16"});
    ASSERT_EQ(runRaytracer(adaptive).exitCode, 0);
    ASSERT_EQ(runRaytracer(small).exitCode, 0);
    EXPECT_EQ(readWholeFile(dir / "adaptive.png"), readWholeFile(dir / "small.png"));
}

TEST(Tiling, AShortRenderIsQuiet) {
    fs::path dir = freshOutputDir("tiling/quiet");
    const std::vector<std::string> args = {
        kShowcase.string(), "-o", (dir / "out.png").string(), "--width", "32", "--height", "24"};
    // The first dispatch of a new kernel may take lavapipe over a second (its LLVM
    // compile, when Mesa's own cache is cold): judge the second run.
    ASSERT_EQ(runRaytracer(args).exitCode, 0);
    ProcessResult run = runRaytracer(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("Render"), std::string::npos) << run.err;
}

// Runs the program with its output on a pseudo-terminal, as in an interactive shell.
ProcessResult runOnTerminal(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {RAYTRACER_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> pointers;
    for (std::string& arg : argv)
        pointers.push_back(arg.data());
    pointers.push_back(nullptr);

    int terminal = -1;
    pid_t child = forkpty(&terminal, nullptr, nullptr, nullptr);
    if (child < 0) throw std::runtime_error("forkpty failed");
    if (child == 0) {
        execv(pointers[0], pointers.data());
        _exit(127);
    }
    ProcessResult result;
    char buffer[4096];
    while (true) {
        ssize_t got = read(terminal, buffer, sizeof buffer);
        if (got > 0)
            result.err.append(buffer, std::size_t(got));
        else if (got < 0 && errno == EINTR)
            continue;
        else
            break; // EIO once the child has closed the terminal
    }
    close(terminal);
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    return result;
}

TEST(Tiling, ProgressIsRedrawnInPlaceOnATerminal) {
    fs::path dir = freshOutputDir("tiling/terminal");
    ProcessResult run =
        runOnTerminal({kShowcase.string(), "-o", (dir / "out.png").string(), "--width", "320",
                       "--height", "240", "--progress", "--region-size", "64", "--no-cache"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::size_t redraws = 0;
    for (std::size_t at = run.err.find("\rRendering 320x240: "); at != std::string::npos;
         at = run.err.find("\rRendering 320x240: ", at + 1))
        ++redraws;
    EXPECT_GE(redraws, 5u) << "one line per finished percentage, 20 regions: " << run.err;
    EXPECT_NE(run.err.find("\rRendering 320x240: 100% ("), std::string::npos) << run.err;
    // Each redraw before the end gives the time so far and an estimate of what is left.
    const std::regex redraw("\rRendering 320x240: [0-9]{1,2}% \\([0-9]+\\.[0-9] s elapsed, "
                            "about [0-9]+\\.[0-9] s left\\)   ");
    EXPECT_GE(std::distance(std::sregex_iterator(run.err.begin(), run.err.end(), redraw),
                            std::sregex_iterator()),
              4)
        << run.err;
    EXPECT_EQ(run.err.find("Rendered "), std::string::npos)
        << "no summary line on a terminal: " << run.err;
}

} // namespace
