// Lists of items by key, made on all threads: for each key, the items that name it, in
// ascending order, as one pass over the items in order would list them (the faces around
// each position of a model, the triangles at each corner of a mesh). One array holds all
// the lists, one after another (compressed rows).
#pragma once

#include "base/parallel.h"
#include "base/populated_memory.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

struct KeyedLists {
    // Key k's items are items[start[k]] up to items[start[k + 1]]; keys + 1 entries.
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> items;
};

// keysOf(item, visit) calls visit(key) for each key of item (a key named twice lists the
// item twice); bound: at least the keys named in all, below 2^32. The items are counted
// and placed with atomic increments, in whatever order the threads come, then each list
// is sorted: the lists are those of one pass in order, whatever the thread count.
template <typename KeysOf>
KeyedLists keyedLists(std::size_t keys, std::size_t items, std::size_t bound,
                      const KeysOf& keysOf) {
    if (bound >= UINT32_MAX)
        throw std::length_error("keyedLists: " + std::to_string(bound) +
                                " entries do not fit 32-bit offsets");
    constexpr std::size_t kGrain = 1 << 14;
    KeyedLists lists;
    resizePopulated(lists.start, keys + 1);
    parallelForRanges(items, kGrain, [&](IndexRange range) {
        for (std::size_t item = range.begin; item < range.end; ++item)
            keysOf(item, [&](std::uint32_t key) {
                std::atomic_ref<std::uint32_t>(lists.start[key + 1])
                    .fetch_add(1, std::memory_order_relaxed);
            });
    });
    std::partial_sum(lists.start.begin(), lists.start.end(), lists.start.begin());
    resizePopulated(lists.items, lists.start.back());
    std::vector<std::uint32_t> next; // where each key's next item goes
    resizePopulated(next, keys);
    std::copy(lists.start.begin(), lists.start.end() - 1, next.begin());
    parallelForRanges(items, kGrain, [&](IndexRange range) {
        for (std::size_t item = range.begin; item < range.end; ++item)
            keysOf(item, [&](std::uint32_t key) {
                const std::uint32_t at = std::atomic_ref<std::uint32_t>(next[key]).fetch_add(
                    1, std::memory_order_relaxed);
                lists.items[at] = std::uint32_t(item);
            });
    });
    parallelForRanges(keys, kGrain, [&](IndexRange range) {
        for (std::size_t key = range.begin; key < range.end; ++key)
            std::sort(lists.items.begin() + lists.start[key],
                      lists.items.begin() + lists.start[key + 1]);
    });
    return lists;
}
