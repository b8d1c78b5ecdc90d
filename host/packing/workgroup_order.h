// The order in which a dispatch's rows of workgroups take the rows of its tiles: the
// workgroups of row k (gl_WorkGroupID.y, in dispatch order) trace the tiles of row
// (k * stride) mod rows (tileOfWorkgroup in shaders/trace.comp; the stride reaches it in
// GpuFrameParams).
//
// Why: lavapipe hands each of its T worker threads one contiguous T-th of a dispatch's
// workgroups at once, in row-major order (Mesa's lp_cs_tpool splits a dispatch statically;
// it does not deal out workgroups as threads free up). With rows in image order, one thread
// traced the top of the image and another the bottom, and the thread whose part held more
// of the scene ran on while the other waited: 1.4 of 2 cores busy on the 100k-triangle
// knot (docs/performance.md). With a stride near rows / phi^2 (the golden ratio's
// low-discrepancy sequence), every contiguous run of rows is a spread-out sample of the
// whole dispatch, whatever T. Rows, not single tiles: the kernel then computes one
// remainder of a small product, exactly, with a float division (lavapipe has no vector
// integer division; three of them per invocation cost test1.scene 4.6% of its
// instructions). A GPU's scheduler starts workgroups as its units free up, so the order
// should not matter there (not measured); it runs the same mapping, one path for every device.
#pragma once

#include <cstdint>

// The most rows a dispatch may have for the mapping: k * stride < rows^2 <= 2^16 is exact in
// a float, and the quotient by rows (below 256) lands at least 1/512 from an integer, far
// beyond the error GLSL allows a division (2.5 ulp). The renderer's dispatches have at most
// 128 rows (1024 pixels).
inline constexpr std::uint32_t kMaxOrderedRows = 256;

// A stride coprime to rows (so that the mapping is a permutation) near rows / phi^2; 1 for
// one or two rows. Throws std::invalid_argument above kMaxOrderedRows.
std::uint32_t rowStride(std::uint32_t rows);
