// Every thread the host starts comes from here: one thread-count policy (--threads N, else
// the hardware's threads) and one way to share work among threads.
//
// The work is handed out one index at a time, so an expensive part (a reflective mesh's
// rows, a large subtree) does not leave the other threads idle; the result never depends
// on which thread ran which index, so callers write each index's result to its own slot.
#pragma once

#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

// The threads host work may use: setWorkerThreads's count, else one per hardware thread.
unsigned workerThreads();
// --threads N; 0 goes back to one per hardware thread.
void setWorkerThreads(unsigned threads);

// Calls body(i) for every i in [0, count) on up to `threads` threads at once (the calling
// thread among them; 0: workerThreads()), and never on more than the hardware's threads:
// more only take turns on its cores (16 on 2 read an OBJ file 15% slower than 2), while
// the work's split (an OBJ file's chunks, a hierarchy's tasks) still follows the count
// asked. Returns when every call has returned. After
// a call throws, no further index is handed out; the exception of the lowest index that
// threw is rethrown once all threads have stopped. Where a thread cannot be started the
// ones running share the work.
void parallelFor(std::size_t count, const std::function<void(std::size_t)>& body,
                 unsigned threads = 0);

// The same for work that keeps state per thread (scratch buffers, a ray query's context):
// each thread calls makeBody() once, then gives every index it takes to the body it got.
using IndexBody = std::function<void(std::size_t)>;
void parallelForPerThread(std::size_t count, const std::function<IndexBody()>& makeBody,
                          unsigned threads = 0);

// How many readers share a text of `bytes`: up to `threads` (0: workerThreads()), none with
// less than minChunkBytes, at least one.
std::size_t chunkCount(std::size_t bytes, unsigned threads, std::size_t minChunkBytes);

// [0, count) cut into consecutive ranges, a few per thread and none shorter than `grain`
// (but the last): how a loop over a large array is shared (parallelFor over the ranges), and,
// for a reduction that must give the bits of one pass, the order its parts are combined in.
struct IndexRange {
    std::size_t begin = 0, end = 0;
};
std::vector<IndexRange> splitRange(std::size_t count, std::size_t grain);

// body(range) for each range of splitRange(count, grain), on all threads: a loop over a
// large array whose iterations write their own elements.
void parallelForRanges(std::size_t count, std::size_t grain,
                       const std::function<void(IndexRange)>& body);

// For each of ranges, how many of the items before it pass: countIn(range) for every range
// on up to `threads` threads (0: workerThreads()), summed in range order; ranges.size() + 1
// entries, the last the total. Where each range's passing items go when they are copied out
// in order on all threads (an ordered compaction).
template <typename CountIn>
std::vector<std::size_t> countsBefore(const std::vector<IndexRange>& ranges, const CountIn& countIn,
                                      unsigned threads = 0) {
    std::vector<std::size_t> before(ranges.size() + 1, 0);
    parallelFor(
        ranges.size(), [&](std::size_t k) { before[k + 1] = countIn(ranges[k]); }, threads);
    for (std::size_t k = 0; k < ranges.size(); ++k)
        before[k + 1] += before[k];
    return before;
}

// pass(range) for each range of splitRange(count, grain) on all threads, the results then
// merged in range order, merge(part, into) adding each to the first range's. The ranges
// depend on the thread count: the result does not when merging is exact in any grouping
// (a minimum, a maximum, a count; the first index of a maximum when merge keeps the earlier).
template <typename Pass, typename Merge>
auto reduceRanges(std::size_t count, std::size_t grain, const Pass& pass, const Merge& merge) {
    using Result = std::invoke_result_t<Pass, IndexRange>;
    const std::vector<IndexRange> ranges = splitRange(count, grain);
    std::vector<Result> parts(ranges.size());
    parallelFor(ranges.size(), [&](std::size_t k) { parts[k] = pass(ranges[k]); });
    Result total = std::move(parts.front());
    for (std::size_t k = 1; k < parts.size(); ++k)
        merge(parts[k], total);
    return total;
}
