#include "render/reference/product_cache_pixels.h"

#include "render/reference/cpu_camera.h"
#include "util/path_sampler.h"

#include <algorithm>
#include <limits>
#include <thread>
#include <utility>

namespace wavelit::render {

std::vector<uint32_t> productCacheEntrySizes(const scene::Scene& scene, const scene::Bvh& bvh,
                                             int width, int height,
                                             const std::function<uint32_t(float)>& entrySize) {
    std::vector<uint32_t> sizes(size_t(width) * size_t(height), 0u);
    traceProductCacheRows(scene, bvh, width, height, 0, height, entrySize, sizes);
    return sizes;
}

void traceProductCacheRows(const scene::Scene& scene, const scene::Bvh& bvh, int width, int height,
                           int firstRow, int endRow,
                           const std::function<uint32_t(float)>& entrySize,
                           std::vector<uint32_t>& sizes) {
    const CpuCamera camera(scene.camera, width, height);
    endRow = std::min(endRow, height);
    auto trace = [&](int rowOffset, int rowStep) {
        for (int y = firstRow + rowOffset; y < endRow; y += rowStep)
            for (int x = 0; x < width; ++x) {
                scene::BvhHit hit;
                uint32_t size = 0u;
                // The pixel centre, as both caches build their entries (jitter 0.5, 0.5).
                if (scene::intersect(bvh, camera.origin(), camera.direction(x, y, 0.5f, 0.5f),
                                     0.0f, std::numeric_limits<float>::max(), hit))
                    size = entrySize(bvh.triangles[hit.triangle].v0[3]);
                sizes[size_t(y) * size_t(width) + size_t(x)] = size;
            }
    };
    const int threads =
        std::min(int(std::clamp(std::thread::hardware_concurrency(), 1u, 16u)), endRow - firstRow);
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
        workers.emplace_back(trace, t, threads);
    trace(0, std::max(threads, 1));
    for (std::thread& w : workers)
        w.join();
}

uint64_t fitProductCacheEntries(std::vector<uint32_t>& sizes, uint64_t fixedUnits,
                                uint64_t maxUnits) {
    std::vector<uint32_t> order;
    uint64_t wanted = fixedUnits;
    for (size_t i = 0; i < sizes.size(); ++i)
        if (sizes[i] != 0u) {
            order.push_back(uint32_t(i));
            wanted += sizes[i];
        }
    if (wanted <= maxUnits)
        return 0;
    // The same share in every part of the image, so the extra noise spreads evenly instead of
    // starting below a line.
    std::sort(order.begin(), order.end(), [](uint32_t a, uint32_t b) {
        return std::pair(util::hashU32(a), a) < std::pair(util::hashU32(b), b);
    });
    uint64_t used = fixedUnits, skipped = 0;
    for (uint32_t i : order) {
        if (used + sizes[i] > maxUnits) {
            sizes[i] = 0u;
            ++skipped;
        } else {
            used += sizes[i];
        }
    }
    return skipped;
}

} // namespace wavelit::render
