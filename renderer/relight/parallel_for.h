// Splits [0, count) into contiguous chunks over `threads` std::threads (the caller's thread runs
// the first chunk). Chunks are fixed by index, so every per-item result is the same whatever the
// thread count: the preview is deterministic and its tests compare bit for bit.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace wavelit::relight {

template <typename F> void parallelFor(size_t count, int threads, F&& body) {
    const size_t workers = std::max<size_t>(1, std::min<size_t>(size_t(std::max(threads, 1)), count));
    if (workers <= 1) {
        for (size_t i = 0; i < count; ++i) body(i);
        return;
    }
    // Interleaved blocks of 64 items balance work whose cost varies across the image (a shadow
    // region in one corner) better than one block per thread.
    constexpr size_t kBlock = 64;
    auto run = [&](size_t worker) {
        for (size_t start = worker * kBlock; start < count; start += workers * kBlock)
            for (size_t i = start, end = std::min(count, start + kBlock); i < end; ++i) body(i);
    };
    std::vector<std::thread> pool;
    for (size_t w = 1; w < workers; ++w) pool.emplace_back(run, w);
    run(0);
    for (std::thread& t : pool) t.join();
}

} // namespace wavelit::relight
