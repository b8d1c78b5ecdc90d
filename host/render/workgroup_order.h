// The order in which a dispatch's workgroups take its tiles: workgroup k (row-major in the
// dispatch grid) traces tile (k * stride) mod count, also row-major (tileOfWorkgroup in
// shaders/trace.comp; the stride reaches it in GpuFrameParams).
//
// Why: lavapipe hands each of its T worker threads one contiguous T-th of a dispatch's
// workgroups at once (Mesa's lp_cs_tpool splits a dispatch statically; it does not deal
// out workgroups as threads free up). With tiles in image order, one thread traced the top
// of the image and another the bottom, and the thread whose half held more of the scene
// ran on while the other waited: 1.4 of 2 cores busy on the 100k-triangle knot
// (docs/performance.md). With a stride near count / phi^2 (the golden ratio's
// low-discrepancy sequence), every contiguous run of workgroups is a spread-out sample of
// the whole dispatch, whatever T. A GPU starts workgroups as its units free up, so the
// order does not matter there; it runs the same mapping, one path for every device.
#pragma once

#include <cstdint>

// The most workgroups a dispatch may have for the mapping: k * stride stays below 2^32.
inline constexpr std::uint32_t kMaxOrderedWorkgroups = 65535;

// A stride coprime to workgroupCount (so that the mapping is a permutation) near
// workgroupCount / phi^2; 1 for one or two workgroups. Throws std::invalid_argument above
// kMaxOrderedWorkgroups.
std::uint32_t workgroupStride(std::uint32_t workgroupCount);
