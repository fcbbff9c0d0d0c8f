// util::parallelFor hands 64-item blocks to whichever worker is free, parallelForWorkers
// interleaves them by index: both run every item exactly once at any count and thread count, and
// parallelForWorkers' item-to-worker map is the documented one (per-worker scratch relies on it).
#include "util/parallel_for.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <vector>

namespace wavelit::util {
namespace {

const size_t kCounts[] = {0, 1, 63, 64, 65, 1000, 4097};
const int kThreads[] = {0, 1, 2, 3, 8};

TEST(ParallelFor, RunsEveryItemExactlyOnce) {
    for (size_t count : kCounts)
        for (int threads : kThreads) {
            std::unique_ptr<std::atomic<int>[]> runs(new std::atomic<int>[count + 1]);
            for (size_t i = 0; i <= count; ++i) runs[i] = 0;
            parallelFor(count, threads, [&](size_t i) { ++runs[i]; });
            for (size_t i = 0; i < count; ++i) ASSERT_EQ(runs[i].load(), 1) << count << " " << threads << " " << i;
            EXPECT_EQ(runs[count].load(), 0);
        }
}

TEST(ParallelFor, WorkersInterleaveBlocksByIndex) {
    for (size_t count : kCounts)
        for (int threads : kThreads) {
            const size_t workers = parallelWorkers(count, threads);
            EXPECT_GE(workers, 1u);
            EXPECT_LE(workers, size_t(std::max(threads, 1)));
            std::vector<int> worker(count, -1); // each item written by one worker only
            std::vector<int> runs(count, 0);
            parallelForWorkers(count, threads, [&](size_t w, size_t i) {
                worker[i] = int(w);
                ++runs[i];
            });
            for (size_t i = 0; i < count; ++i) {
                ASSERT_EQ(runs[i], 1) << count << " " << threads << " " << i;
                ASSERT_EQ(size_t(worker[i]), (i / kParallelBlock) % workers) << count << " " << threads << " " << i;
            }
        }
}

} // namespace
} // namespace wavelit::util
