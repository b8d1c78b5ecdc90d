#include "base/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace {

std::atomic<unsigned> requestedThreads{0};

} // namespace

unsigned workerThreads() {
    const unsigned requested = requestedThreads.load(std::memory_order_relaxed);
    return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

void setWorkerThreads(unsigned threads) {
    requestedThreads.store(threads, std::memory_order_relaxed);
}

void parallelFor(std::size_t count, const std::function<void(std::size_t)>& body,
                 unsigned threads) {
    parallelForPerThread(
        count, [&] { return IndexBody(std::ref(body)); }, threads);
}

void parallelForPerThread(std::size_t count, const std::function<IndexBody()>& makeBody,
                          unsigned threads) {
    if (threads == 0) threads = workerThreads();
    static const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t workers = std::min<std::size_t>(std::min(threads, hardware), count);
    if (workers <= 1) {
        if (count == 0) return;
        const IndexBody body = makeBody();
        for (std::size_t i = 0; i < count; ++i)
            body(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex errorLock;
    std::size_t errorIndex = count; // the lowest index that threw so far
    std::exception_ptr error;
    auto work = [&] {
        IndexBody body;
        try {
            body = makeBody();
        } catch (...) {
            const std::lock_guard<std::mutex> hold(errorLock);
            if (!error) error = std::current_exception();
            failed = true;
            return;
        }
        // An index once taken is run, so every index below one that threw has run too.
        while (!failed) {
            const std::size_t i = next++;
            if (i >= count) break;
            try {
                body(i);
            } catch (...) {
                const std::lock_guard<std::mutex> hold(errorLock);
                if (i < errorIndex) errorIndex = i, error = std::current_exception();
                failed = true;
            }
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t k = 1; k < workers; ++k) {
        try {
            pool.emplace_back(work);
        } catch (const std::system_error&) {
            break; // no more threads to be had: the ones running share the work
        }
    }
    work();
    for (std::thread& thread : pool)
        thread.join();
    if (error) std::rethrow_exception(error);
}

std::size_t chunkCount(std::size_t bytes, unsigned threads, std::size_t minChunkBytes) {
    if (threads == 0) threads = workerThreads();
    return std::max<std::size_t>(
        1, std::min<std::size_t>(threads, bytes / std::max<std::size_t>(minChunkBytes, 1)));
}

std::vector<IndexRange> splitRange(std::size_t count, std::size_t grain) {
    const std::size_t most = std::max<std::size_t>(1, 4 * std::size_t(workerThreads()));
    const std::size_t ranges =
        std::clamp<std::size_t>(count / std::max<std::size_t>(grain, 1), 1, most);
    std::vector<IndexRange> split(ranges);
    for (std::size_t k = 0; k < ranges; ++k)
        split[k] = {count * k / ranges, count * (k + 1) / ranges};
    return split;
}

void parallelForRanges(std::size_t count, std::size_t grain,
                       const std::function<void(IndexRange)>& body) {
    const std::vector<IndexRange> ranges = splitRange(count, grain);
    parallelFor(ranges.size(), [&](std::size_t k) { body(ranges[k]); });
}
