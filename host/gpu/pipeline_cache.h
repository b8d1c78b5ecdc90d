// The on-disk cache that makes a second start quick: the trace kernel's SPIR-V (glslang
// then runs only when a shader source changed) and the driver's VkPipelineCache data (a
// GPU driver can then skip its own compile). It lives in $XDG_CACHE_HOME/raytracer, else
// $HOME/.cache/raytracer. Best effort throughout: a file that is missing, damaged,
// foreign or unwritable costs a rebuild and a one-line note on stderr, never a failure.
#pragma once

#include "gpu/context.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

// The cache folder, created when missing. Empty, with a note on stderr, when neither
// candidate can be written; empty and silent when enabled is false (--no-cache).
std::filesystem::path userCacheDirectory(bool enabled);

// What a cached SPIR-V file holds: the kernel as glslang compiled it (spirv-KEY.bin), or
// that kernel specialised for one specialization (specialized-KEY.bin,
// host/gpu/spirv_specializer.h). Each kind keeps its own newest files.
enum class SpirvStage { Compiled, Specialized };

// SPIR-V stored under key (a hash of everything that went into it), or nothing when there
// is none or it is unusable (a note says why).
std::optional<std::vector<std::uint32_t>> loadCachedSpirv(const std::filesystem::path& directory,
                                                          std::uint64_t key,
                                                          SpirvStage stage = SpirvStage::Compiled);
void storeCachedSpirv(const std::filesystem::path& directory, std::uint64_t key,
                      const std::vector<std::uint32_t>& spirv,
                      SpirvStage stage = SpirvStage::Compiled);

// A VkPipelineCache for one shader on one device, seeded from its file when the file is
// whole and its VkPipelineCacheHeaderVersionOne names this device and driver.
struct PipelineCache {
    VkPipelineCache cache = VK_NULL_HANDLE; // VK_NULL_HANDLE without a cache folder
    std::filesystem::path file;
    std::uint64_t key = 0;
    std::vector<std::uint8_t> loaded; // what the file held, to skip rewriting the same bytes
};

// shaderKey names the shader the driver is given (its SPIR-V and specialization).
PipelineCache openPipelineCache(const Context& context, const std::filesystem::path& directory,
                                std::uint64_t shaderKey);

// Writes the driver's current data back when it differs from what was loaded.
void savePipelineCache(const Context& context, const PipelineCache& cache);

void destroyPipelineCache(const Context& context, PipelineCache& cache);

// Why driver data cannot be given to this device (empty when it can): it must start
// with a VkPipelineCacheHeaderVersionOne whose vendorID, deviceID and pipelineCacheUUID
// are the device's. Checked here because not every driver checks before parsing.
std::string pipelineCacheMismatch(const std::vector<std::uint8_t>& data,
                                  const VkPhysicalDeviceProperties& device);
