// The order of a dispatch's rows of workgroups over its rows of tiles
// (host/packing/workgroup_order.h): a permutation for every dispatch height the renderer
// makes, the same remainder as the kernel's float arithmetic, and one that gives each
// contiguous share of the workgroups (what one lavapipe worker thread takes) rows from the
// whole image, not a band of it.
#include "packing/workgroup_order.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace {

// The row of tiles that row k of workgroups traces, as tileOfWorkgroup in
// shaders/trace.comp computes it: in floats.
std::uint32_t rowOf(std::uint32_t k, std::uint32_t stride, std::uint32_t rows) {
    const std::uint32_t product = k * stride;
    const auto quotient = std::uint32_t((float(product) + 0.5f) / float(rows));
    return product - quotient * rows;
}

TEST(WorkgroupOrder, EveryRowIsTracedOnceForEveryDispatchHeight) {
    for (std::uint32_t rows = 1; rows <= kMaxOrderedRows; ++rows) {
        const std::uint32_t stride = rowStride(rows);
        std::vector<bool> seen(rows, false);
        for (std::uint32_t k = 0; k < rows; ++k) {
            const std::uint32_t row = rowOf(k, stride, rows);
            ASSERT_EQ(row, k * stride % rows) << rows << " rows, row " << k;
            ASSERT_FALSE(seen[row]) << rows << " rows: row " << row << " twice";
            seen[row] = true;
        }
    }
}

// lavapipe's split: T threads, each a contiguous count / T of the workgroups (the remainder
// one by one at the end). A 640 x 480 frame is 80 x 60 workgroups; for 1 to 4 threads each
// thread's share of the workgroups should fall evenly on the image's quarters (by rows): within
// 6 points of a quarter each.
TEST(WorkgroupOrder, EachThreadsShareCoversTheWholeImage) {
    const std::uint32_t columns = 80, rows = 60, count = columns * rows;
    const std::uint32_t stride = rowStride(rows);
    for (std::uint32_t threads = 1; threads <= 4; ++threads) {
        const std::uint32_t share = count / threads;
        for (std::uint32_t thread = 0; thread < threads; ++thread) {
            std::uint32_t inQuarter[4] = {};
            for (std::uint32_t k = thread * share; k < (thread + 1) * share; ++k)
                ++inQuarter[rowOf(k / columns, stride, rows) * 4 / rows];
            for (std::uint32_t quarter = 0; quarter < 4; ++quarter)
                EXPECT_NEAR(double(inQuarter[quarter]) / share, 0.25, 0.06)
                    << threads << " threads, thread " << thread << ", quarter " << quarter;
        }
    }
}

TEST(WorkgroupOrder, ImageOrderWouldGiveEachThreadOneBand) {
    // The control: stride 1 (image order) puts thread 0 of 2 entirely in the top half.
    const std::uint32_t rows = 60;
    for (std::uint32_t k = 0; k < rows / 2; ++k)
        EXPECT_LT(rowOf(k, 1, rows), rows / 2);
}

TEST(WorkgroupOrder, TooManyRowsIsAnError) {
    EXPECT_NO_THROW(rowStride(kMaxOrderedRows));
    EXPECT_THROW(rowStride(kMaxOrderedRows + 1), std::invalid_argument);
}

} // namespace
