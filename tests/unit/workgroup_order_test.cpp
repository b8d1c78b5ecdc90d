// The workgroups' order over a dispatch's tiles (host/render/workgroup_order.h): a
// permutation for every dispatch size the renderer makes, and one that gives each
// contiguous share of the workgroups (what one lavapipe worker thread takes) tiles from the
// whole image, not a band of it.
#include "render/workgroup_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

// The tile workgroup k traces, as tileOfWorkgroup in shaders/trace.comp computes it.
std::uint32_t tileOf(std::uint32_t k, std::uint32_t stride, std::uint32_t count) {
    return std::uint32_t((std::uint64_t(k) * stride) % count);
}

TEST(WorkgroupOrder, EveryTileIsTracedOnceForEveryDispatchSize) {
    // Every count up to 4096, and the largest dispatch (1024 x 1024 pixels, 128 x 128 tiles).
    std::vector<std::uint32_t> counts;
    for (std::uint32_t count = 1; count <= 4096; ++count)
        counts.push_back(count);
    counts.push_back(128 * 128);
    for (std::uint32_t count : counts) {
        const std::uint32_t stride = workgroupStride(count);
        ASSERT_LT(std::uint64_t(count - 1) * stride, std::uint64_t(1) << 32) << count;
        std::vector<bool> seen(count, false);
        for (std::uint32_t k = 0; k < count; ++k) {
            const std::uint32_t tile = tileOf(k, stride, count);
            ASSERT_FALSE(seen[tile]) << "count " << count << ": tile " << tile << " twice";
            seen[tile] = true;
        }
    }
}

// lavapipe's split: T threads, each a contiguous count / T of the workgroups (the
// remainder one by one at the end). Each share's tiles should be spread evenly over the
// image's rows: here, the share of them in each quarter of the rows is within 3 points of
// a quarter, for a 640 x 480 frame (80 x 60 tiles) and 1 to 16 threads.
TEST(WorkgroupOrder, EachThreadsShareCoversTheWholeImage) {
    const std::uint32_t columns = 80, rows = 60, count = columns * rows;
    const std::uint32_t stride = workgroupStride(count);
    for (std::uint32_t threads = 1; threads <= 16; ++threads) {
        const std::uint32_t share = count / threads;
        for (std::uint32_t thread = 0; thread < threads; ++thread) {
            std::uint32_t inQuarter[4] = {};
            for (std::uint32_t k = thread * share; k < (thread + 1) * share; ++k)
                ++inQuarter[tileOf(k, stride, count) / columns * 4 / rows];
            for (std::uint32_t quarter = 0; quarter < 4; ++quarter)
                EXPECT_NEAR(double(inQuarter[quarter]) / share, 0.25, 0.03)
                    << threads << " threads, thread " << thread << ", quarter " << quarter;
        }
    }
}

TEST(WorkgroupOrder, ImageOrderWouldGiveEachThreadOneBand) {
    // The control: stride 1 (image order) puts thread 0 of 2 entirely in the top half.
    const std::uint32_t columns = 80, rows = 60, count = columns * rows;
    std::uint32_t inTopHalf = 0;
    for (std::uint32_t k = 0; k < count / 2; ++k)
        inTopHalf += tileOf(k, 1, count) / columns < rows / 2;
    EXPECT_EQ(inTopHalf, count / 2);
}

TEST(WorkgroupOrder, TooManyWorkgroupsIsAnError) {
    EXPECT_NO_THROW(workgroupStride(kMaxOrderedWorkgroups));
    EXPECT_THROW(workgroupStride(kMaxOrderedWorkgroups + 1), std::invalid_argument);
}

} // namespace
