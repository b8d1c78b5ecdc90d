// The on-disk shader and pipeline cache (host/gpu/pipeline_cache.h) as a user meets it: the
// first run fills it, later runs use it, and a damaged, truncated, empty or foreign file
// costs a note and a rebuild, never a failure or a different image. --no-cache writes
// nothing. Every run gets its own XDG_CACHE_HOME; Mesa's own shader cache is kept in
// one shared folder so that lavapipe does not recompile its code for every fresh home.
#include "test_support.h"

#include "base/hash.h"
#include "gpu/cache_file.h"
#include "gpu/pipeline_cache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>

namespace {

namespace fs = std::filesystem;

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file << bytes;
}

std::vector<fs::path> filesIn(const fs::path& folder) {
    std::vector<fs::path> files;
    if (fs::is_directory(folder))
        for (const auto& entry : fs::directory_iterator(folder))
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

class StartupCache : public testing::Test {
  protected:
    void SetUp() override {
        setenv("MESA_SHADER_CACHE_DIR", (fs::path(TEST_OUTPUT_DIR) / "mesa-shader-cache").c_str(),
               1);
        dir_ = freshOutputDir(std::string("startup/") +
                              testing::UnitTest::GetInstance()->current_test_info()->name());
        scene_ = dir_ / "scene.scene";
        writeTextFile(scene_,
                      "3\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -3\nrad: 1\ndif: 0.5 0.2 0.2\n"
                      "spe: 0.3 0.3 0.3\nshi: 10\ntriangle\npos: -2 -1 -4\nnor: 0 1 0\n"
                      "dif: 0.2 0.6 0.2\nspe: 0 0 0\nshi: 1\npos: 2 -1 -4\nnor: 0 1 0\n"
                      "dif: 0.2 0.6 0.2\nspe: 0 0 0\nshi: 1\npos: 0 -1 -1\nnor: 0 1 0\n"
                      "dif: 0.2 0.6 0.2\nspe: 0 0 0\nshi: 1\nlight\npos: 2 2 0\ncol: 1 1 1\n");
    }
    void TearDown() override {
        unsetenv("XDG_CACHE_HOME");
        unsetenv("MESA_SHADER_CACHE_DIR");
    }

    // Renders the scene with XDG_CACHE_HOME = cacheHome into dir_/NAME.png.
    ProcessResult render(const fs::path& cacheHome, const std::string& name,
                         std::vector<std::string> extra = {}) {
        setenv("XDG_CACHE_HOME", cacheHome.c_str(), 1);
        std::vector<std::string> args = {scene_.string(),
                                         "-o",
                                         (dir_ / (name + ".png")).string(),
                                         "--width",
                                         "64",
                                         "--height",
                                         "48",
                                         "--validate"};
        args.insert(args.end(), extra.begin(), extra.end());
        return runRaytracer(args);
    }

    std::string png(const std::string& name) { return readWholeFile(dir_ / (name + ".png")); }

    // A cache folder filled by one run, and the image of a run without any cache.
    fs::path filledCache() {
        ProcessResult uncached = render(dir_ / "unused-home", "uncached", {"--no-cache"});
        EXPECT_EQ(uncached.exitCode, 0) << uncached.err;
        fs::path home = dir_ / "home";
        ProcessResult first = render(home, "first");
        EXPECT_EQ(first.exitCode, 0) << first.err;
        EXPECT_EQ(first.err.find("note:"), std::string::npos) << first.err;
        return home / "raytracer";
    }

    fs::path dir_, scene_;
};

TEST_F(StartupCache, FirstRunFillsTheCacheAndLaterRunsUseIt) {
    fs::path cache = filledCache();
    std::vector<fs::path> files = filesIn(cache);
    ASSERT_EQ(files.size(), 3u)
        << "expected the SPIR-V, the SPIR-V specialised for the scene and the pipeline cache file";
    EXPECT_EQ(files[0].filename().string().rfind("pipeline-", 0), 0u) << files[0];
    EXPECT_EQ(files[1].filename().string().rfind("specialized-", 0), 0u) << files[1];
    EXPECT_EQ(files[2].filename().string().rfind("spirv-", 0), 0u) << files[2];
    EXPECT_EQ(png("first"), png("uncached"));

    std::vector<fs::file_time_type> written;
    for (const fs::path& file : files)
        written.push_back(fs::last_write_time(file));
    ProcessResult second = render(dir_ / "home", "second");
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(second.err.find("note:"), std::string::npos) << second.err;
    EXPECT_EQ(png("second"), png("uncached"));
    EXPECT_EQ(filesIn(cache), files) << "a warm start adds no files";
    for (std::size_t i = 0; i < files.size(); ++i)
        EXPECT_EQ(fs::last_write_time(files[i]), written[i]) << files[i] << " was rewritten";
}

TEST_F(StartupCache, NoCacheWritesNothing) {
    fs::path home = dir_ / "home";
    ProcessResult run = render(home, "uncached", {"--no-cache"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(fs::exists(home / "raytracer"));
    EXPECT_EQ(run.err.find("note:"), std::string::npos) << run.err;
}

// Each kind of damage, applied to every file of a filled cache: the run still succeeds
// with the same image, prints one note per file, and leaves a good cache behind.
TEST_F(StartupCache, DamagedFilesAreIgnoredWithANoteAndRebuilt) {
    const fs::path good = filledCache();
    std::mt19937 random(1234);
    const std::vector<std::pair<std::string, std::function<std::string(const std::string&)>>>
        damages = {
            {"random",
             [&](const std::string& bytes) {
                 std::string noise(bytes.size(), '\0');
                 for (char& c : noise)
                     c = static_cast<char>(random());
                 return noise;
             }},
            {"truncated",
             [](const std::string& bytes) { return bytes.substr(0, bytes.size() - 7); }},
            {"half", [](const std::string& bytes) { return bytes.substr(0, bytes.size() / 2); }},
            {"empty", [](const std::string&) { return std::string(); }},
            {"flipped",
             [](const std::string& bytes) {
                 std::string flipped = bytes;
                 flipped[flipped.size() - 3] ^= 0x40;
                 return flipped;
             }},
        };
    for (const auto& [name, damage] : damages) {
        SCOPED_TRACE(name);
        fs::path home = dir_ / ("home-" + name);
        fs::create_directories(home);
        fs::copy(good, home / "raytracer");
        std::vector<fs::path> files = filesIn(home / "raytracer");
        for (const fs::path& file : files)
            writeBytes(file, damage(readWholeFile(file)));

        ProcessResult run = render(home, name);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(png(name), png("uncached"));
        for (const fs::path& file : files)
            EXPECT_NE(run.err.find("note: ignoring cache file " + file.string() + ": "),
                      std::string::npos)
                << run.err;

        ProcessResult again = render(home, name + "-again");
        ASSERT_EQ(again.exitCode, 0) << again.err;
        EXPECT_EQ(again.err.find("note:"), std::string::npos) << "not rebuilt: " << again.err;
        EXPECT_EQ(png(name + "-again"), png("uncached"));
    }
}

// A pipeline cache file that is whole (checksum right) but whose Vulkan header names
// another device: the check of vendorID, deviceID and pipelineCacheUUID must catch it
// before the driver sees it.
TEST_F(StartupCache, PipelineCacheOfAnotherDeviceIsIgnoredWithANote) {
    const fs::path good = filledCache();
    for (const char* field : {"vendor", "uuid"}) {
        SCOPED_TRACE(field);
        fs::path home = dir_ / (std::string("home-") + field);
        fs::create_directories(home);
        fs::copy(good, home / "raytracer");
        fs::path file = filesIn(home / "raytracer")[0];
        ASSERT_EQ(file.filename().string().rfind("pipeline-", 0), 0u);
        std::string bytes = readWholeFile(file);
        CacheFileHeader header;
        ASSERT_GE(bytes.size(), sizeof header + sizeof(VkPipelineCacheHeaderVersionOne));
        std::memcpy(&header, bytes.data(), sizeof header);
        std::string payload = bytes.substr(sizeof header);
        VkPipelineCacheHeaderVersionOne vulkan;
        std::memcpy(&vulkan, payload.data(), sizeof vulkan);
        if (std::string(field) == "vendor")
            vulkan.vendorID ^= 0x1234;
        else
            vulkan.pipelineCacheUUID[5] ^= 0x01;
        std::memcpy(payload.data(), &vulkan, sizeof vulkan);
        header.payloadHash = hashBytes(payload.data(), payload.size());
        writeBytes(file,
                   std::string(reinterpret_cast<const char*>(&header), sizeof header) + payload);

        ProcessResult run = render(home, field);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(png(field), png("uncached"));
        EXPECT_NE(run.err.find("note: ignoring cache file " + file.string() +
                               ": made by another device or driver"),
                  std::string::npos)
            << run.err;
        EXPECT_FALSE(hasValidationMessage(run)) << run.err;
    }
}

// Kernel variants never share a cache file: fp64 is compiled from the same sources with
// another preamble, so it gets its own SPIR-V file (and specialised SPIR-V and pipeline
// files); a method switch is a specialization constant of the same SPIR-V, so it gets only
// its own specialised SPIR-V and pipeline files.
// After all of them, each variant still starts warm (no note, nothing rewritten) and
// draws what it drew uncached.
TEST_F(StartupCache, PrecisionsAndSpecializationsKeepSeparateFiles) {
    fs::path cache = filledCache();
    ASSERT_EQ(filesIn(cache).size(), 3u);
    ASSERT_EQ(render(dir_ / "unused-home", "fp64-uncached", {"--no-cache", "--precision", "fp64"})
                  .exitCode,
              0);
    ProcessResult fp64 = render(dir_ / "home", "fp64", {"--precision", "fp64"});
    ASSERT_EQ(fp64.exitCode, 0) << fp64.err;
    EXPECT_EQ(fp64.err.find("note:"), std::string::npos) << fp64.err;
    EXPECT_EQ(png("fp64"), png("fp64-uncached"));
    auto countPrefix = [&](const std::string& prefix) {
        std::vector<fs::path> files = filesIn(cache);
        return std::count_if(files.begin(), files.end(), [&](const fs::path& file) {
            return file.filename().string().rfind(prefix, 0) == 0;
        });
    };
    EXPECT_EQ(countPrefix("spirv-"), 2) << "fp32 and fp64 need two SPIR-V files";
    EXPECT_EQ(countPrefix("specialized-"), 2);
    EXPECT_EQ(countPrefix("pipeline-"), 2);

    ProcessResult naive = render(dir_ / "home", "naive", {"--sphere-test", "naive"});
    ASSERT_EQ(naive.exitCode, 0) << naive.err;
    EXPECT_EQ(countPrefix("spirv-"), 2) << "a specialization constant needs no new SPIR-V";
    EXPECT_EQ(countPrefix("specialized-"), 3) << "but a specialised SPIR-V file of its own";
    EXPECT_EQ(countPrefix("pipeline-"), 3) << "and a pipeline file of its own";

    const std::vector<fs::path> files = filesIn(cache);
    std::vector<fs::file_time_type> times;
    for (const fs::path& file : files)
        times.push_back(fs::last_write_time(file));
    for (const auto& [name, flags] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"fp32-warm", {}},
             {"fp64-warm", {"--precision", "fp64"}},
             {"naive-warm", {"--sphere-test", "naive"}}}) {
        ProcessResult warm = render(dir_ / "home", name, flags);
        ASSERT_EQ(warm.exitCode, 0) << warm.err;
        EXPECT_EQ(warm.err.find("note:"), std::string::npos) << name << ": " << warm.err;
    }
    EXPECT_EQ(png("fp32-warm"), png("uncached"));
    EXPECT_EQ(png("fp64-warm"), png("fp64-uncached"));
    EXPECT_EQ(png("naive-warm"), png("naive"));
    EXPECT_EQ(filesIn(cache), files) << "warm starts add no files";
    for (std::size_t i = 0; i < files.size(); ++i)
        EXPECT_EQ(fs::last_write_time(files[i]), times[i]) << files[i] << " was rewritten";
}

TEST_F(StartupCache, WithoutAWritableFolderThereIsNoCacheAndANote) {
    ProcessResult uncached = render(dir_ / "unused-home", "uncached", {"--no-cache"});
    ASSERT_EQ(uncached.exitCode, 0) << uncached.err;
    // Nothing can be created under /proc, not even by root.
    const char* home = std::getenv("HOME");
    const std::string savedHome = home ? home : "";
    setenv("HOME", "/proc/no-such-home", 1);
    ProcessResult run = render("/proc/no-such-cache", "nowhere");
    setenv("HOME", savedHome.c_str(), 1);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("note: no writable cache folder"), std::string::npos) << run.err;
    EXPECT_EQ(png("nowhere"), png("uncached"));
}

// The header check alone, with made-up devices.
TEST(PipelineCacheHeader, OnlyTheSameDeviceAndDriverMatch) {
    VkPhysicalDeviceProperties device{};
    device.vendorID = 0x10005;
    device.deviceID = 0x42;
    for (std::uint32_t i = 0; i < VK_UUID_SIZE; ++i)
        device.pipelineCacheUUID[i] = static_cast<std::uint8_t>(i);
    VkPipelineCacheHeaderVersionOne header{};
    header.headerSize = sizeof header;
    header.headerVersion = VK_PIPELINE_CACHE_HEADER_VERSION_ONE;
    header.vendorID = device.vendorID;
    header.deviceID = device.deviceID;
    std::memcpy(header.pipelineCacheUUID, device.pipelineCacheUUID, VK_UUID_SIZE);
    auto bytesOf = [](const VkPipelineCacheHeaderVersionOne& h, std::size_t extra = 0) {
        std::vector<std::uint8_t> bytes(sizeof h + extra, 0xab);
        std::memcpy(bytes.data(), &h, sizeof h);
        return bytes;
    };
    EXPECT_EQ(pipelineCacheMismatch(bytesOf(header, 100), device), "");

    VkPipelineCacheHeaderVersionOne other = header;
    other.deviceID = 0x43;
    EXPECT_NE(pipelineCacheMismatch(bytesOf(other), device).find("another device or driver"),
              std::string::npos);
    other = header;
    other.pipelineCacheUUID[15] ^= 1;
    EXPECT_NE(pipelineCacheMismatch(bytesOf(other), device).find("another device or driver"),
              std::string::npos);
    other = header;
    other.headerVersion = static_cast<VkPipelineCacheHeaderVersion>(7);
    EXPECT_NE(pipelineCacheMismatch(bytesOf(other), device).find("not a Vulkan pipeline cache"),
              std::string::npos);
    other = header;
    other.headerSize = 4096; // claims more than the data holds
    EXPECT_NE(pipelineCacheMismatch(bytesOf(other), device).find("not a Vulkan pipeline cache"),
              std::string::npos);
    EXPECT_NE(pipelineCacheMismatch({1, 2, 3}, device).find("too short"), std::string::npos);
}

// The container alone: what each kind of damage is called.
TEST(CacheFile, DamageIsNamed) {
    fs::path dir = freshOutputDir("startup/cache-file");
    fs::path file = dir / "x.bin";
    const std::string payload = "some payload bytes";
    ASSERT_EQ(writeCacheFile(file, CacheKind::Spirv, 77, payload.data(), payload.size()), "");
    EXPECT_TRUE(filesIn(dir).size() == 1) << "no temporary file is left behind";
    std::string problem;
    auto read = readCacheFile(file, CacheKind::Spirv, 77, problem);
    ASSERT_TRUE(read.has_value()) << problem;
    EXPECT_EQ(std::string(read->begin(), read->end()), payload);

    auto problemWith = [&](const std::string& bytes, CacheKind kind = CacheKind::Spirv,
                           std::uint64_t key = 77) {
        fs::path damaged = dir / "damaged.bin";
        writeBytes(damaged, bytes);
        std::string why;
        EXPECT_FALSE(readCacheFile(damaged, kind, key, why).has_value());
        return why;
    };
    const std::string whole = readWholeFile(file);
    EXPECT_EQ(problemWith(""), "the file is empty");
    EXPECT_EQ(problemWith("PNG\r\n and more bytes than a header holds, surely more"),
              "not a Raytracer cache file");
    EXPECT_NE(problemWith(whole.substr(0, 20)).find("truncated"), std::string::npos);
    EXPECT_NE(problemWith(whole.substr(0, whole.size() - 1)).find("truncated"), std::string::npos);
    EXPECT_NE(problemWith(whole + "x").find("padded"), std::string::npos);
    EXPECT_NE(problemWith(whole, CacheKind::Pipeline).find("another version"), std::string::npos);
    EXPECT_NE(problemWith(whole, CacheKind::Spirv, 78).find("key mismatch"), std::string::npos);
    std::string flipped = whole;
    flipped.back() ^= 1;
    EXPECT_NE(problemWith(flipped).find("checksum"), std::string::npos);

    std::string none;
    EXPECT_FALSE(readCacheFile(dir / "absent.bin", CacheKind::Spirv, 77, none).has_value());
    EXPECT_EQ(none, "") << "a missing file is not a problem";
}

// Every shader edit adds a SPIR-V file; the folder keeps only the newest few.
TEST(CacheFile, OldFilesArePruned) {
    fs::path dir = freshOutputDir("startup/prune");
    const std::vector<std::uint32_t> spirv = {0x07230203u, 0x00010500u, 0u, 1u, 0u};
    for (std::uint64_t key = 1; key <= 12; ++key)
        storeCachedSpirv(dir, key, spirv);
    EXPECT_EQ(filesIn(dir).size(), 8u);
    ASSERT_TRUE(loadCachedSpirv(dir, 12).has_value()) << "the newest file is kept";
    EXPECT_EQ(*loadCachedSpirv(dir, 12), spirv);
    // Specialised SPIR-V is pruned among its own kind: many scenes' specialisations never
    // push out the compiled kernel they came from.
    for (std::uint64_t key = 101; key <= 112; ++key)
        storeCachedSpirv(dir, key, spirv, SpirvStage::Specialized);
    EXPECT_EQ(filesIn(dir).size(), 16u);
    EXPECT_TRUE(loadCachedSpirv(dir, 12).has_value());
    EXPECT_TRUE(loadCachedSpirv(dir, 112, SpirvStage::Specialized).has_value());
    EXPECT_FALSE(loadCachedSpirv(dir, 12, SpirvStage::Specialized).has_value())
        << "the two kinds do not share files";
}

} // namespace
