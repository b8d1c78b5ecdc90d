// Gives each distinct value an index in order of first appearance, comparing values bit for
// bit: how the packer shares materials and vertices, and how a model's corners become a
// mesh's vertices.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

// A 64-bit hash of the raw bytes of a trivially copyable value, so that exactly equal
// values (bit for bit) are merged and nothing else is.
template <typename T> std::uint64_t dedupHash(const T& value) {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % 4 == 0);
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    std::uint64_t hash = 0x9E3779B97F4A7C15ull;
    std::size_t i = 0;
    for (; i + 8 <= sizeof(T); i += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes + i, 8);
        hash = std::rotl((hash ^ word) * 0xFF51AFD7ED558CCDull, 29);
    }
    if (i < sizeof(T)) {
        std::uint32_t word;
        std::memcpy(&word, bytes + i, 4);
        hash = std::rotl((hash ^ word) * 0xFF51AFD7ED558CCDull, 29);
    }
    // MurmurHash3's finaliser: every input bit reaches every output bit.
    hash ^= hash >> 33;
    hash *= 0xC4CEB9FE1A85EC53ull;
    return hash ^ (hash >> 33);
}

// Gives each distinct value an index, in order of first appearance. An open-addressing
// table (linear probing, at most half full) of 8-byte slots holding the value's index
// and 32 bits of its hash, so that a probe rarely looks at a value that differs: a
// million-triangle mesh makes three million look-ups, and std::unordered_map's node per
// entry made them cost half a second.
template <typename T> class Deduplicator {
  public:
    Deduplicator(std::vector<T>& values, std::size_t expectedDistinct) : values_(values) {
        slots_.resize(std::bit_ceil(std::max<std::size_t>(2 * expectedDistinct, 16)));
    }

    std::uint32_t indexOf(const T& value) {
        const std::uint64_t hash = dedupHash(value);
        const auto tag = static_cast<std::uint32_t>(hash >> 32);
        const std::size_t mask = slots_.size() - 1;
        std::size_t at = hash & mask;
        for (; slots_[at].indexPlusOne != 0; at = (at + 1) & mask) {
            const Slot slot = slots_[at];
            if (slot.tag == tag &&
                std::memcmp(&values_[slot.indexPlusOne - 1], &value, sizeof(T)) == 0)
                return slot.indexPlusOne - 1;
        }
        const auto index = static_cast<std::uint32_t>(values_.size());
        values_.push_back(value);
        slots_[at] = {index + 1, tag};
        if (2 * values_.size() > slots_.size()) grow();
        return index;
    }

  private:
    struct Slot {
        std::uint32_t indexPlusOne = 0; // 0: empty
        std::uint32_t tag = 0;          // the hash's upper half
    };

    void grow() {
        std::vector<Slot> slots(2 * slots_.size());
        const std::size_t mask = slots.size() - 1;
        for (std::size_t i = 0; i < values_.size(); ++i) {
            const std::uint64_t hash = dedupHash(values_[i]);
            std::size_t at = hash & mask;
            while (slots[at].indexPlusOne != 0)
                at = (at + 1) & mask;
            slots[at] = {std::uint32_t(i + 1), static_cast<std::uint32_t>(hash >> 32)};
        }
        slots_.swap(slots);
    }

    std::vector<T>& values_;
    std::vector<Slot> slots_;
};
