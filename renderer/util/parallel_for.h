// Runs body over [0, count) on `threads` std::threads (the caller's thread is worker 0), in
// blocks of 64 items: work whose cost varies across the range (a shadow region in one corner of
// a preview, the poles of an env map) spreads over the workers better than with one block each.
// Every item is run exactly once, so results that do not depend on the order of the items are
// the same whatever the thread count (the relight preview and the sampler tables are compared
// bit for bit between thread counts). parallelForWorkers interleaves the blocks by index (which
// worker runs an item depends only on its index and the worker count: per-worker scratch);
// parallelFor hands them to whichever worker is free.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace wavelit::util {

inline constexpr size_t kParallelBlock = 64;

// The number of workers parallelFor* uses for `count` items on `threads` threads: at least 1, and
// no more than there are blocks (a worker without a block would be a thread, and per-worker
// scratch, for nothing: 256 env rows on a 64-core machine are 4 blocks).
inline size_t parallelWorkers(size_t count, int threads) {
    const size_t blocks = (count + kParallelBlock - 1) / kParallelBlock;
    return std::max<size_t>(1, std::min<size_t>(size_t(std::max(threads, 1)), blocks));
}

// `threads`, or every hardware thread (at least 1) for threads <= 0.
inline int threadsOrHardware(int threads) {
    return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

// run(worker) for worker in [0, workers): the caller's thread is worker 0, the others are new.
template <typename Run> void runOnWorkers(size_t workers, Run&& run) {
    std::vector<std::thread> pool;
    for (size_t w = 1; w < workers; ++w) pool.emplace_back([&run, w] { run(w); });
    run(size_t(0));
    for (std::thread& t : pool) t.join();
}

// body(worker, item), worker in [0, parallelWorkers(count, threads)): for per-worker scratch.
template <typename F> void parallelForWorkers(size_t count, int threads, F&& body) {
    const size_t workers = parallelWorkers(count, threads);
    runOnWorkers(workers, [&](size_t worker) {
        for (size_t start = worker * kParallelBlock; start < count; start += workers * kParallelBlock)
            for (size_t i = start, end = std::min(count, start + kParallelBlock); i < end; ++i) body(worker, i);
    });
}

// body(item), the blocks handed out in order to whichever worker is free: the item's cost may
// cluster (a moved object's own pixels, a few rows of a preview), and a fixed interleave gave one
// of two workers up to a third more of a drag step's work than the other. Which thread runs an
// item is not fixed, so body must not keep state across items (per item results are the same).
template <typename F> void parallelFor(size_t count, int threads, F&& body) {
    std::atomic<size_t> next{0};
    runOnWorkers(parallelWorkers(count, threads), [&](size_t) {
        for (size_t start = next.fetch_add(kParallelBlock); start < count; start = next.fetch_add(kParallelBlock))
            for (size_t i = start, end = std::min(count, start + kParallelBlock); i < end; ++i) body(i);
    });
}

} // namespace wavelit::util
