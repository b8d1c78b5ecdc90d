#include "gpu/cache_file.h"

#include "base/hash.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>
#include <unistd.h>

namespace {

constexpr char kMagic[8] = {'R', 'T', 'C', 'A', 'C', 'H', 'E', '\0'};

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

std::optional<std::vector<std::uint8_t>> readWholeFile(const std::filesystem::path& path,
                                                       std::string& problem) {
    File file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) {
        if (errno != ENOENT) problem = std::string("cannot open it: ") + std::strerror(errno);
        return std::nullopt;
    }
    std::vector<std::uint8_t> bytes;
    std::uint8_t chunk[1 << 16];
    std::size_t got = 0;
    while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0)
        bytes.insert(bytes.end(), chunk, chunk + got);
    if (std::ferror(file.get())) {
        problem = "cannot read it";
        return std::nullopt;
    }
    return bytes;
}

} // namespace

std::optional<std::vector<std::uint8_t>> readCacheFile(const std::filesystem::path& path,
                                                       CacheKind kind, std::uint64_t key,
                                                       std::string& problem) {
    problem.clear();
    std::optional<std::vector<std::uint8_t>> bytes = readWholeFile(path, problem);
    if (!bytes) return std::nullopt;
    if (bytes->empty()) {
        problem = "the file is empty";
        return std::nullopt;
    }
    CacheFileHeader header{};
    const std::size_t magicBytes = std::min(bytes->size(), sizeof kMagic);
    if (std::memcmp(bytes->data(), kMagic, magicBytes) != 0) {
        problem = "not a Raytracer cache file";
        return std::nullopt;
    }
    if (bytes->size() < sizeof header) {
        problem = "truncated: " + std::to_string(bytes->size()) + " bytes, shorter than the header";
        return std::nullopt;
    }
    std::memcpy(&header, bytes->data(), sizeof header);
    if (header.formatVersion != kCacheFormatVersion ||
        header.kind != static_cast<std::uint32_t>(kind)) {
        problem = "written by another version of Raytracer (format " +
                  std::to_string(header.formatVersion) + ", kind " + std::to_string(header.kind) +
                  ")";
        return std::nullopt;
    }
    const std::uint64_t available = bytes->size() - sizeof header;
    if (header.payloadBytes != available) {
        problem = "truncated or padded: the header announces " +
                  std::to_string(header.payloadBytes) + " bytes of data, the file holds " +
                  std::to_string(available);
        return std::nullopt;
    }
    if (header.key != key) {
        problem = "made from other inputs (key mismatch)";
        return std::nullopt;
    }
    std::vector<std::uint8_t> payload(bytes->begin() + sizeof header, bytes->end());
    if (hashBytes(payload.data(), payload.size()) != header.payloadHash) {
        problem = "damaged (checksum mismatch)";
        return std::nullopt;
    }
    return payload;
}

std::string writeCacheFile(const std::filesystem::path& path, CacheKind kind, std::uint64_t key,
                           const void* payload, std::size_t size) {
    CacheFileHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.formatVersion = kCacheFormatVersion;
    header.kind = static_cast<std::uint32_t>(kind);
    header.key = key;
    header.payloadBytes = size;
    header.payloadHash = hashBytes(payload, size);

    // A name of our own, so two processes filling the cache at once never write into
    // each other's temporary file; the last rename wins, and either file is whole.
    std::filesystem::path temporary = path;
    temporary += ".tmp-" + std::to_string(getpid());
    std::string error;
    {
        File file(std::fopen(temporary.c_str(), "wb"), &std::fclose);
        if (!file) return "cannot create " + temporary.string() + ": " + std::strerror(errno);
        bool written = std::fwrite(&header, sizeof header, 1, file.get()) == 1 &&
                       (size == 0 || std::fwrite(payload, size, 1, file.get()) == 1);
        if (!written) error = std::string("cannot write: ") + std::strerror(errno);
        if (std::fclose(file.release()) != 0 && error.empty())
            error = std::string("cannot write: ") + std::strerror(errno);
    }
    std::error_code status;
    if (error.empty()) {
        std::filesystem::rename(temporary, path, status);
        if (status) error = "cannot rename into place: " + status.message();
    }
    if (!error.empty()) std::filesystem::remove(temporary, status);
    return error;
}
