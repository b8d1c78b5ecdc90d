#include "gpu/pipeline_cache.h"

#include "base/hash.h"
#include "base/notes.h"
#include "gpu/cache_file.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <unistd.h>

namespace {

// Each shader edit or driver update makes new files; the oldest beyond this many of a
// kind are removed, so the folder stays small without ever evicting a file in use.
constexpr std::size_t kFilesKeptPerKind = 8;

constexpr std::uint32_t kSpirvMagic = 0x07230203;

std::string hex(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

std::string spirvPrefix(SpirvStage stage) {
    return stage == SpirvStage::Specialized ? "specialized-" : "spirv-";
}

void noteIgnored(const std::filesystem::path& file, const std::string& problem) {
    note("note: ignoring cache file %s: %s; rebuilding it\n", file.c_str(), problem.c_str());
}

void noteUnwritable(const std::filesystem::path& file, const std::string& problem) {
    note("note: cannot update cache file %s: %s\n", file.c_str(), problem.c_str());
}

// Removes the least recently written files named PREFIX* beyond kFilesKeptPerKind.
void pruneOldFiles(const std::filesystem::path& directory, const std::string& prefix) {
    std::error_code error;
    std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> files;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) == 0 && name.find(".tmp-") == std::string::npos)
            files.emplace_back(entry.last_write_time(error), entry.path());
    }
    if (files.size() <= kFilesKeptPerKind) return;
    std::sort(files.begin(), files.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = kFilesKeptPerKind; i < files.size(); ++i)
        std::filesystem::remove(files[i].second, error);
}

void store(const std::filesystem::path& directory, const std::string& prefix, std::uint64_t key,
           CacheKind kind, const void* payload, std::size_t size) {
    const std::filesystem::path file = directory / (prefix + hex(key) + ".bin");
    std::string error = writeCacheFile(file, kind, key, payload, size);
    if (!error.empty()) {
        noteUnwritable(file, error);
        return;
    }
    pruneOldFiles(directory, prefix);
}

bool isWritableDirectory(const std::filesystem::path& directory) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    return !error && std::filesystem::is_directory(directory, error) &&
           access(directory.c_str(), W_OK | X_OK) == 0;
}

} // namespace

std::filesystem::path userCacheDirectory(bool enabled) {
    if (!enabled) return {};
    // XDG Base Directory: a relative $XDG_CACHE_HOME is invalid and must be ignored.
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    std::vector<std::filesystem::path> candidates;
    if (xdg && xdg[0] == '/') candidates.push_back(std::filesystem::path(xdg) / "raytracer");
    if (home && home[0] == '/')
        candidates.push_back(std::filesystem::path(home) / ".cache" / "raytracer");
    for (const std::filesystem::path& directory : candidates)
        if (isWritableDirectory(directory)) return directory;
    note("note: no writable cache folder ($XDG_CACHE_HOME/raytracer or "
         "$HOME/.cache/raytracer); shaders are compiled on every start\n");
    return {};
}

std::optional<std::vector<std::uint32_t>> loadCachedSpirv(const std::filesystem::path& directory,
                                                          std::uint64_t key, SpirvStage stage) {
    if (directory.empty()) return std::nullopt;
    const std::filesystem::path file = directory / (spirvPrefix(stage) + hex(key) + ".bin");
    std::string problem;
    std::optional<std::vector<std::uint8_t>> bytes =
        readCacheFile(file, CacheKind::Spirv, key, problem);
    if (bytes && (bytes->size() < 20 || bytes->size() % 4 != 0)) problem = "not SPIR-V (size)";
    std::vector<std::uint32_t> spirv;
    if (bytes && problem.empty()) {
        spirv.resize(bytes->size() / 4);
        std::memcpy(spirv.data(), bytes->data(), bytes->size());
        if (spirv[0] != kSpirvMagic) problem = "not SPIR-V (magic number)";
    }
    if (!problem.empty()) {
        noteIgnored(file, problem);
        return std::nullopt;
    }
    if (!bytes) return std::nullopt;
    return spirv;
}

void storeCachedSpirv(const std::filesystem::path& directory, std::uint64_t key,
                      const std::vector<std::uint32_t>& spirv, SpirvStage stage) {
    if (directory.empty()) return;
    store(directory, spirvPrefix(stage), key, CacheKind::Spirv, spirv.data(),
          spirv.size() * sizeof(std::uint32_t));
}

std::string pipelineCacheMismatch(const std::vector<std::uint8_t>& data,
                                  const VkPhysicalDeviceProperties& device) {
    VkPipelineCacheHeaderVersionOne header{};
    if (data.size() < sizeof header) return "too short for a Vulkan pipeline cache header";
    std::memcpy(&header, data.data(), sizeof header);
    if (header.headerVersion != VK_PIPELINE_CACHE_HEADER_VERSION_ONE ||
        header.headerSize < sizeof header || header.headerSize > data.size())
        return "not a Vulkan pipeline cache (header version " +
               std::to_string(header.headerVersion) + ", header size " +
               std::to_string(header.headerSize) + ")";
    if (header.vendorID != device.vendorID || header.deviceID != device.deviceID ||
        std::memcmp(header.pipelineCacheUUID, device.pipelineCacheUUID, VK_UUID_SIZE) != 0) {
        char ids[64];
        std::snprintf(ids, sizeof ids, "vendor 0x%x, device 0x%x", header.vendorID,
                      header.deviceID);
        return std::string("made by another device or driver (") + ids + ")";
    }
    return {};
}

PipelineCache openPipelineCache(const Context& context, const std::filesystem::path& directory,
                                std::uint64_t shaderKey) {
    PipelineCache result;
    if (directory.empty()) return result;
    // The file name covers the shader and the exact device and driver, so two GPUs or two
    // builds never take turns overwriting one file; the header check below still guards
    // against a file copied or damaged into place.
    const VkPhysicalDeviceProperties& device = context.properties;
    std::uint64_t key = hashBytes(&shaderKey, sizeof shaderKey);
    key = hashBytes(&device.vendorID, sizeof device.vendorID, key);
    key = hashBytes(&device.deviceID, sizeof device.deviceID, key);
    key = hashBytes(&device.driverVersion, sizeof device.driverVersion, key);
    key = hashBytes(device.pipelineCacheUUID, VK_UUID_SIZE, key);
    result.key = key;
    result.file = directory / ("pipeline-" + hex(key) + ".bin");

    std::string problem;
    std::optional<std::vector<std::uint8_t>> data =
        readCacheFile(result.file, CacheKind::Pipeline, key, problem);
    if (data && problem.empty()) problem = pipelineCacheMismatch(*data, device);
    if (!problem.empty())
        noteIgnored(result.file, problem);
    else if (data)
        result.loaded = std::move(*data);

    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    info.initialDataSize = result.loaded.size();
    info.pInitialData = result.loaded.empty() ? nullptr : result.loaded.data();
    VK_CHECK(vkCreatePipelineCache(context.device, &info, nullptr, &result.cache));
    return result;
}

void savePipelineCache(const Context& context, const PipelineCache& cache) {
    if (!cache.cache) return;
    std::size_t size = 0;
    VK_CHECK(vkGetPipelineCacheData(context.device, cache.cache, &size, nullptr));
    std::vector<std::uint8_t> data(size);
    // VK_INCOMPLETE only if the data grew in between; what was written is still valid.
    VkResult result = vkGetPipelineCacheData(context.device, cache.cache, &size, data.data());
    if (result != VK_INCOMPLETE) VK_CHECK(result);
    data.resize(size);
    if (data == cache.loaded) return;
    // Never store what a later start would refuse (a driver that returns no header).
    if (!pipelineCacheMismatch(data, context.properties).empty()) return;
    store(cache.file.parent_path(), "pipeline-", cache.key, CacheKind::Pipeline, data.data(),
          data.size());
}

void destroyPipelineCache(const Context& context, PipelineCache& cache) {
    if (cache.cache) vkDestroyPipelineCache(context.device, cache.cache, nullptr);
    cache = PipelineCache{};
}
