// The small helpers of host/base/ that every report and every thread goes through: JSON
// text (base/json.h), the thread policy and parallel loops (base/parallel.h), and the
// deduplication on all threads (base/ordered_dedup.h).
#include "base/json.h"
#include "base/ordered_dedup.h"
#include "base/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

TEST(Json, StringsEscapeQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(jsonString("plain"), "\"plain\"");
    EXPECT_EQ(jsonString("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(jsonString(std::string("tab\there\nnul\0!", 14)),
              "\"tab\\u0009here\\u000anul\\u0000!\"");
    EXPECT_EQ(jsonString("caf\xC3\xA9"), "\"caf\xC3\xA9\""); // UTF-8 passes as it is
}

TEST(Json, NumbersHaveTheirDigitsAndNonFiniteValuesAreNull) {
    EXPECT_EQ(jsonNumber(1.23456), "1.235");
    EXPECT_EQ(jsonNumber(0.1f, 9), "0.100000001");
    EXPECT_EQ(jsonNumber(0.1, 17), "0.10000000000000001");
    EXPECT_EQ(jsonNumber(std::numeric_limits<double>::infinity(), 9), "null");
    EXPECT_EQ(jsonNumber(std::nan(""), 17), "null");
    struct Vector {
        float x, y, z;
    };
    EXPECT_EQ(jsonTriple(Vector{1.0f, -2.5f, NAN}, 9), "[1, -2.5, null]");
}

TEST(Parallel, ThreadPolicyIsTheRequestedCountElseTheHardwares) {
    setWorkerThreads(3);
    EXPECT_EQ(workerThreads(), 3u);
    setWorkerThreads(0);
    EXPECT_EQ(workerThreads(), std::max(1u, std::thread::hardware_concurrency()));
}

TEST(Parallel, EveryIndexRunsOnceOnAtMostTheGivenThreads) {
    for (unsigned threads : {1u, 2u, 4u}) {
        std::vector<std::atomic<int>> runs(1000);
        std::mutex lock;
        std::set<std::thread::id> seen;
        parallelFor(
            runs.size(),
            [&](std::size_t i) {
                ++runs[i];
                const std::lock_guard<std::mutex> hold(lock);
                seen.insert(std::this_thread::get_id());
            },
            threads);
        for (const auto& count : runs)
            ASSERT_EQ(count.load(), 1);
        EXPECT_LE(seen.size(), threads);
    }
    parallelFor(
        0, [](std::size_t) { FAIL() << "no index to run"; }, 2);
}

TEST(Parallel, PerThreadBodiesAreMadeOncePerThread) {
    std::atomic<int> made{0};
    std::vector<int> done(64, 0);
    parallelForPerThread(
        done.size(),
        [&]() -> IndexBody {
            ++made;
            return [&](std::size_t i) { done[i] = 1; };
        },
        2);
    EXPECT_LE(made.load(), 2);
    EXPECT_GE(made.load(), 1);
    for (int d : done)
        EXPECT_EQ(d, 1);
}

TEST(Parallel, TheLowestFailingIndexIsRethrownAfterEveryThreadStopped) {
    for (unsigned threads : {1u, 2u, 3u}) {
        std::atomic<int> running{0};
        try {
            parallelFor(
                100,
                [&](std::size_t i) {
                    ++running;
                    if (i == 7 || i == 9) {
                        --running;
                        throw std::runtime_error("index " + std::to_string(i));
                    }
                    --running;
                },
                threads);
            FAIL() << "no exception";
        } catch (const std::runtime_error& error) {
            EXPECT_EQ(running.load(), 0);
            EXPECT_STREQ(error.what(), "index 7") << threads << " threads";
        }
    }
}

// orderedDedup gives every value the index Deduplicator gives it called on the values in
// turn, for any thread count and any share of repeats, across shards and blocks.
TEST(OrderedDedup, TheIndicesOfDeduplicatorInTurn) {
    struct Value {
        std::uint32_t a, b;
    };
    for (const std::uint32_t distinct : {1u, 7u, 1000u, 200000u})
        for (const unsigned threads : {1u, 2u, 5u}) {
            std::mt19937 random(distinct);
            std::vector<Value> sequence(100000);
            for (Value& value : sequence)
                value = {std::uint32_t(random() % distinct), 42};
            std::vector<Value> expectedValues;
            Deduplicator<Value> one(expectedValues, 16);
            std::vector<std::uint32_t> expected;
            for (const Value& value : sequence)
                expected.push_back(one.indexOf(value));
            setWorkerThreads(threads);
            const OrderedDedup all =
                orderedDedup<Value>(sequence.size(), [&](std::size_t i) { return sequence[i]; });
            setWorkerThreads(0);
            EXPECT_EQ(all.indexOf, expected) << distinct << " distinct, " << threads << " threads";
            ASSERT_EQ(all.firstOf.size(), expectedValues.size());
            for (std::size_t k = 0; k < all.firstOf.size(); ++k) {
                EXPECT_EQ(sequence[all.firstOf[k]].a, expectedValues[k].a);
                EXPECT_EQ(expected[all.firstOf[k]], k);
            }
        }
    EXPECT_TRUE(orderedDedup<std::uint32_t>(0, [](std::size_t) { return 0u; }).indexOf.empty());
}
