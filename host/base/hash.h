// 64-bit FNV-1a over bytes: the fingerprint of the on-disk cache's files and keys and of
// watched files. Guards against damage and staleness, not against an attacker.
#pragma once

#include <cstddef>
#include <cstdint>

inline constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;

// seed chains several calls: hashBytes(b, n, hashBytes(a, m)) hashes a then b.
inline std::uint64_t hashBytes(const void* data, std::size_t size,
                               std::uint64_t seed = kFnvOffsetBasis) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    std::uint64_t hash = seed;
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= 0x100000001b3ull;
    }
    return hash;
}
