// One file of the on-disk cache: a fixed header that says what the payload was made
// from and lets a reader check that it arrived whole, then the payload. Written to a
// temporary file and renamed, so a reader never sees half a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

enum class CacheKind : std::uint32_t {
    Spirv = 1,    // the trace kernel compiled by glslang; key: hash of its sources
    Pipeline = 2, // vkGetPipelineCacheData; key: hash of the SPIR-V and the device
};

// Native byte order: the cache belongs to one machine.
struct CacheFileHeader {
    char magic[8];               // "RTCACHE" and a NUL
    std::uint32_t formatVersion; // kCacheFormatVersion
    std::uint32_t kind;          // CacheKind
    std::uint64_t key;           // what the payload was made from
    std::uint64_t payloadBytes;
    std::uint64_t payloadHash; // hashBytes(payload)
};
static_assert(sizeof(CacheFileHeader) == 40, "the header's size is part of the file format");

inline constexpr std::uint32_t kCacheFormatVersion = 1;

// The payload when path holds a whole, undamaged file of this kind and key. Otherwise
// nothing; problem then says why, or stays empty when there is simply no file.
std::optional<std::vector<std::uint8_t>> readCacheFile(const std::filesystem::path& path,
                                                       CacheKind kind, std::uint64_t key,
                                                       std::string& problem);

// Writes PATH.tmp-PID, then renames it over path. Returns an error message, empty on success.
std::string writeCacheFile(const std::filesystem::path& path, CacheKind kind, std::uint64_t key,
                           const void* payload, std::size_t size);
