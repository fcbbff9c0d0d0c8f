#include "render/gpu/product_cache.h"

#include "render/reference/cpu_camera.h"
#include "util/path_sampler.h"

#include <algorithm>
#include <limits>
#include <thread>
#include <utility>

namespace wavelit::render {

uint32_t gpuProductCachePyramidWords() {
    return ((1u << (2 * (kGpuMaxProductLevel + 1))) - 1u) / 3u;
}

uint32_t gpuProductCachePyramidEntryWords() {
    return GpuProductCacheLayout::kPyramidAt + gpuProductCachePyramidWords();
}

GpuProductCacheLayout layoutGpuProductCache(const scene::Scene& scene, const scene::Bvh& bvh,
                                            int width, int height,
                                            const std::vector<GpuSamplerMaterial>& samplerMaterials,
                                            uint64_t maxBytes) {
    GpuProductCacheLayout layout;
    const size_t pixels = size_t(width) * size_t(height);
    const CpuCamera camera(scene.camera, width, height);
    const uint32_t pyramidEntryWords = gpuProductCachePyramidEntryWords();
    static_assert(GpuProductCacheLayout::kHeaderWords % 2 == 0 &&
                  GpuProductCacheLayout::kPyramidAt % 2 == 1);
    // Each pixel's entry size (0: none) from its centre ray, rows shared among threads (every
    // scene or camera edit lays the cache out again: one ray per pixel on the render thread cost
    // ~0.7 CPU-s at 512^2), then the offsets in row order, so the layout is deterministic.
    std::vector<uint32_t> sizes(pixels, 0u);
    auto trace = [&](int firstRow, int rowStep) {
        for (int y = firstRow; y < height; y += rowStep)
            for (int x = 0; x < width; ++x) {
                scene::BvhHit hit;
                // The pixel centre, as the kernel's build pass traces it (jitter 0.5, 0.5).
                if (!scene::intersect(bvh, camera.origin(), camera.direction(x, y, 0.5f, 0.5f),
                                      0.0f, std::numeric_limits<float>::max(), hit))
                    continue;
                // The kernel's material index: min(uint(max(v0.w, 0)), materialCount - 1).
                const float w = bvh.triangles[hit.triangle].v0[3];
                const size_t m = std::min(size_t(std::max(w, 0.0f)), samplerMaterials.size() - 1);
                const GpuSamplerMaterial& sm = samplerMaterials[m];
                if (sm.mode != kGpuSamplerProduct && sm.mode != kGpuSamplerBsdfLobe)
                    continue;
                const bool pyramid = sm.mode == kGpuSamplerProduct;
                sizes[size_t(y) * size_t(width) + size_t(x)] =
                    pyramid ? pyramidEntryWords : GpuProductCacheLayout::kHeaderWords;
            }
    };
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
        workers.emplace_back(trace, t, threads);
    trace(0, threads);
    for (std::thread& w : workers)
        w.join();
    // When the entries do not all fit, those of the pixels first in a hashed order get one until
    // the buffer is full (the rest use `mis`'s technique): the same share in every part of the
    // image, so the extra noise spreads evenly instead of starting below a line.
    std::vector<uint32_t> order;
    const uint64_t firstEntry = uint64_t(pixels) + (pixels & 1u); // entries on 8-byte boundaries
    uint64_t wanted = firstEntry;
    for (size_t i = 0; i < pixels; ++i)
        if (sizes[i] != 0u) {
            order.push_back(uint32_t(i));
            wanted += sizes[i];
        }
    if (wanted * 4u > maxBytes) {
        std::sort(order.begin(), order.end(), [](uint32_t a, uint32_t b) {
            return std::pair(util::hashU32(a), a) < std::pair(util::hashU32(b), b);
        });
        uint64_t used = firstEntry;
        for (uint32_t i : order) {
            if ((used + sizes[i]) * 4u > maxBytes) {
                sizes[i] = 0u;
                ++layout.skipped;
            } else {
                used += sizes[i];
            }
        }
    }
    layout.words.assign(pixels, GpuProductCacheLayout::kNoEntry);
    uint64_t next = firstEntry;
    for (size_t i = 0; i < pixels; ++i) {
        if (sizes[i] == 0u)
            continue;
        layout.words[i] = uint32_t(next);
        next += sizes[i];
        ++layout.entries;
        layout.pyramidEntries += sizes[i] > GpuProductCacheLayout::kHeaderWords ? 1u : 0u;
    }
    layout.words.resize(size_t(next), 0u);
    return layout;
}

} // namespace wavelit::render
