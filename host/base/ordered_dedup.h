// Deduplicator's indices for a whole sequence at once, on all threads: each value of the
// sequence gets the index of its value among the distinct ones in order of first
// appearance, bit for bit what Deduplicator::indexOf gives called on the values in turn.
// The values are hashed in blocks, sent by their hash to shards that each find their values'
// first appearances in sequence order (a table a shard's size, which the cache holds better
// than one of the whole), then the first appearances are ranked in sequence order.
#pragma once

#include "base/deduplicator.h"
#include "base/parallel.h"
#include "base/release.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

struct OrderedDedup {
    std::vector<std::uint32_t> indexOf; // each value's distinct index
    std::vector<std::uint32_t> firstOf; // each distinct index's first value in the sequence
};

// valueAt(i) gives the i-th value (a T, compared bit for bit) for i in [0, count).
template <typename T, typename ValueAt>
OrderedDedup orderedDedup(std::size_t count, const ValueAt& valueAt) {
    constexpr unsigned kShardBits = 6;
    constexpr std::size_t kShards = std::size_t(1) << kShardBits;
    const std::vector<IndexRange> blocks = splitRange(count, 1 << 14);
    std::vector<std::uint64_t> hashes(count);
    std::vector<std::size_t> perShard(blocks.size() * kShards, 0); // [block][shard]
    parallelFor(blocks.size(), [&](std::size_t b) {
        std::size_t* counts = &perShard[b * kShards];
        for (std::size_t i = blocks[b].begin; i < blocks[b].end; ++i) {
            hashes[i] = dedupHash<T>(valueAt(i));
            ++counts[hashes[i] >> (64 - kShardBits)];
        }
    });
    // Each shard's values in sequence order: shard by shard, block by block.
    std::vector<std::size_t> shardStart(kShards + 1, 0);
    std::size_t at = 0;
    for (std::size_t s = 0; s < kShards; ++s) {
        shardStart[s] = at;
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            const std::size_t n = perShard[b * kShards + s];
            perShard[b * kShards + s] = at;
            at += n;
        }
    }
    shardStart[kShards] = at;
    std::vector<std::uint32_t> order(count);
    parallelFor(blocks.size(), [&](std::size_t b) {
        std::size_t* next = &perShard[b * kShards];
        for (std::size_t i = blocks[b].begin; i < blocks[b].end; ++i)
            order[next[hashes[i] >> (64 - kShardBits)]++] = std::uint32_t(i);
    });
    release(perShard);

    // first[i]: the first value of the sequence equal to value i.
    std::vector<std::uint32_t> first(count);
    parallelFor(kShards, [&](std::size_t s) {
        const std::size_t n = shardStart[s + 1] - shardStart[s];
        if (n == 0) return;
        std::vector<std::uint32_t> slots(std::bit_ceil(2 * n), 0); // value + 1; 0: empty
        const std::size_t mask = slots.size() - 1;
        for (std::size_t k = shardStart[s]; k < shardStart[s + 1]; ++k) {
            const std::uint32_t i = order[k];
            std::size_t slot = hashes[i] & mask;
            first[i] = i;
            for (; slots[slot] != 0; slot = (slot + 1) & mask) {
                const std::uint32_t other = slots[slot] - 1;
                if (hashes[other] != hashes[i]) continue;
                // The values are read only where the hashes agree: a value that repeats
                // none before it (most of a mesh's) is never read here.
                const T value = valueAt(i), otherValue = valueAt(other);
                if (std::memcmp(&otherValue, &value, sizeof(T)) == 0) {
                    first[i] = other;
                    break;
                }
            }
            if (first[i] == i) slots[slot] = i + 1;
        }
    });
    release(order);
    release(hashes);

    // The first appearances ranked in sequence order, then every value given its first's.
    const std::vector<std::size_t> firstsBefore = countsBefore(blocks, [&](IndexRange block) {
        std::size_t n = 0;
        for (std::size_t i = block.begin; i < block.end; ++i)
            n += first[i] == i;
        return n;
    });
    OrderedDedup result;
    result.indexOf.resize(count);
    result.firstOf.resize(firstsBefore.back());
    parallelFor(blocks.size(), [&](std::size_t b) {
        auto rank = std::uint32_t(firstsBefore[b]);
        for (std::size_t i = blocks[b].begin; i < blocks[b].end; ++i)
            if (first[i] == i) {
                result.firstOf[rank] = std::uint32_t(i);
                result.indexOf[i] = rank++;
            }
    });
    parallelFor(blocks.size(), [&](std::size_t b) {
        for (std::size_t i = blocks[b].begin; i < blocks[b].end; ++i)
            if (first[i] != i) result.indexOf[i] = result.indexOf[first[i]];
    });
    return result;
}
