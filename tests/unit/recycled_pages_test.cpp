// Large blocks whose freed pages the next block takes (base/recycled_pages.h): a freed
// block's pages are kept and then moved into a new block, contents and all (so they were not
// new pages); a piece that covers a block alone is used where it lies; only blocks of its
// own are taken back; PagesGivenBack and trimRecycledPages give the kept pages back; blocks
// stay whole under threads.
#include "base/recycled_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20;

// Each test starts from no kept pages; none leaves a block live.
class RecycledPages : public ::testing::Test {
  protected:
    void SetUp() override {
        trimRecycledPages();
        ASSERT_EQ(recycledPagesState().liveBlocks, 0u);
    }
    void TearDown() override { trimRecycledPages(); }
};

std::uint8_t* allocateBytes(std::size_t bytes) {
    auto* block = static_cast<std::uint8_t*>(allocateRecycled(bytes));
    EXPECT_NE(block, nullptr);
    return block;
}

bool allEqual(const std::uint8_t* bytes, std::size_t count, std::uint8_t value) {
    for (std::size_t i = 0; i < count; ++i)
        if (bytes[i] != value) return false;
    return true;
}

TEST_F(RecycledPages, AFreedBlocksPagesMoveIntoTheNextWithTheirContents) {
    std::uint8_t* first = allocateBytes(3 * kMiB);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(first) % 4096, 0u);
    std::memset(first, 0xAB, 3 * kMiB);
    EXPECT_EQ(recycledPagesState().liveBytes, 3 * kMiB);
    ASSERT_TRUE(releaseRecycled(first));
    EXPECT_EQ(recycledPagesState().keptBytes, 3 * kMiB);
    EXPECT_EQ(recycledPagesState().liveBlocks, 0u);

    // Larger than what is kept: the kept pages first, still holding what was written, then
    // new (zero) pages.
    std::uint8_t* second = allocateBytes(5 * kMiB);
    EXPECT_EQ(recycledPagesState().keptBytes, 0u);
    EXPECT_TRUE(allEqual(second, 3 * kMiB, 0xAB));
    EXPECT_TRUE(allEqual(second + 3 * kMiB, 2 * kMiB, 0));
    std::memset(second, 0x11, 5 * kMiB);
    ASSERT_TRUE(releaseRecycled(second));
    EXPECT_EQ(recycledPagesState().keptBytes, 5 * kMiB);
    EXPECT_EQ(recycledPagesState().keptPieces, 2u);

    // Both pieces moved again into one block, which is whole.
    std::uint8_t* third = allocateBytes(5 * kMiB);
    EXPECT_TRUE(allEqual(third, 5 * kMiB, 0x11));
    EXPECT_EQ(recycledPagesState().keptBytes, 0u);
    EXPECT_TRUE(releaseRecycled(third));
}

TEST_F(RecycledPages, TheSmallestPieceThatCoversABlockIsUsedWhereItLies) {
    std::uint8_t* small = allocateBytes(kMiB);
    std::uint8_t* large = allocateBytes(4 * kMiB);
    std::uint8_t* larger = allocateBytes(8 * kMiB);
    ASSERT_TRUE(releaseRecycled(small));
    ASSERT_TRUE(releaseRecycled(large));
    ASSERT_TRUE(releaseRecycled(larger));
    std::uint8_t* block = allocateBytes(2 * kMiB + 100); // rounded up to whole pages
    EXPECT_EQ(block, large);
    EXPECT_EQ(recycledPagesState().keptBytes, 13 * kMiB - (2 * kMiB + 4096));
    std::memset(block, 1, 2 * kMiB + 100);
    // The rest of that piece is kept on its own, and covers a block too.
    std::uint8_t* rest = allocateBytes(2 * kMiB - 4096);
    EXPECT_EQ(rest, large + 2 * kMiB + 4096);
    EXPECT_TRUE(releaseRecycled(block));
    EXPECT_TRUE(releaseRecycled(rest));
}

TEST_F(RecycledPages, OnlyItsOwnBlocksAreTakenBack) {
    void* other = std::malloc(64);
    EXPECT_FALSE(releaseRecycled(other));
    std::free(other);
    alignas(4096) static std::uint8_t page[4096];
    EXPECT_FALSE(releaseRecycled(page)); // page-aligned, but not a block
    std::uint8_t* block = allocateBytes(kMiB);
    EXPECT_FALSE(releaseRecycled(block + 4096)); // inside a block
    EXPECT_EQ(recycledPagesState().liveBlocks, 1u);
    EXPECT_TRUE(releaseRecycled(block));
    EXPECT_FALSE(releaseRecycled(block)); // already given back
}

TEST_F(RecycledPages, PagesGivenBackKeepsNothingWhileItLives) {
    std::uint8_t* kept = allocateBytes(2 * kMiB);
    std::uint8_t* during = allocateBytes(2 * kMiB);
    ASSERT_TRUE(releaseRecycled(kept));
    EXPECT_EQ(recycledPagesState().keptBytes, 2 * kMiB);
    {
        const PagesGivenBack givenBack;
        EXPECT_EQ(recycledPagesState().keptBytes, 0u);
        EXPECT_TRUE(releaseRecycled(during));
        EXPECT_EQ(recycledPagesState().keptBytes, 0u);
        EXPECT_EQ(recycledPagesState().liveBlocks, 0u);
    }
    std::uint8_t* after = allocateBytes(kMiB);
    EXPECT_TRUE(releaseRecycled(after));
    EXPECT_EQ(recycledPagesState().keptBytes, kMiB); // kept again once it is gone
    trimRecycledPages();
    EXPECT_EQ(recycledPagesState().keptBytes, 0u);
    EXPECT_EQ(recycledPagesState().keptPieces, 0u);
}

TEST_F(RecycledPages, ManySmallPiecesAreNotAllKept) {
    std::vector<void*> blocks;
    for (int i = 0; i < 5000; ++i)
        blocks.push_back(allocateRecycled(4096));
    for (void* block : blocks)
        ASSERT_TRUE(releaseRecycled(block));
    EXPECT_LE(recycledPagesState().keptPieces, 4096u);
    EXPECT_EQ(recycledPagesState().keptBytes, recycledPagesState().keptPieces * 4096);
}

TEST_F(RecycledPages, BlocksStayWholeOnManyThreads) {
    constexpr int kThreads = 4, kRounds = 200;
    std::vector<std::thread> threads;
    std::vector<int> broken(kThreads, 0);
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([t, &broken] {
            std::uint32_t state = 12345u + std::uint32_t(t);
            for (int round = 0; round < kRounds; ++round) {
                state = state * 1664525u + 1013904223u;
                const std::size_t bytes = (1 + (state >> 24) % 24) * 65536 + (state >> 8) % 4096;
                auto* block = static_cast<std::uint8_t*>(allocateRecycled(bytes));
                const auto mark = std::uint8_t(t * kRounds + round);
                std::memset(block, mark, bytes);
                std::this_thread::yield();
                broken[std::size_t(t)] += !allEqual(block, bytes, mark);
                broken[std::size_t(t)] += !releaseRecycled(block);
            }
        });
    for (std::thread& thread : threads)
        thread.join();
    for (int t = 0; t < kThreads; ++t)
        EXPECT_EQ(broken[std::size_t(t)], 0) << "thread " << t;
    EXPECT_EQ(recycledPagesState().liveBlocks, 0u);
    EXPECT_EQ(recycledPagesState().liveBytes, 0u);
}

} // namespace
