#include "render/gpu/product_cache.h"

#include "render/reference/product_cache_pixels.h"

#include <algorithm>

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
    const uint32_t pyramidEntryWords = gpuProductCachePyramidEntryWords();
    static_assert(GpuProductCacheLayout::kHeaderWords % 2 == 0 &&
                  GpuProductCacheLayout::kPyramidAt % 2 == 1);
    // Which pixels get an entry, by the rule both tracers' caches share (product_cache_pixels.h):
    // the centre hit's material forms a product (the kernel's material index:
    // min(uint(max(v0.w, 0)), materialCount - 1)), sized by whether it holds a pyramid.
    std::vector<uint32_t> sizes = productCacheEntrySizes(
        scene, bvh, width, height, [&](float w) -> uint32_t {
            const size_t m = std::min(size_t(std::max(w, 0.0f)), samplerMaterials.size() - 1);
            const GpuSamplerMaterial& sm = samplerMaterials[m];
            if (sm.mode != kGpuSamplerProduct && sm.mode != kGpuSamplerBsdfLobe)
                return 0u;
            return sm.mode == kGpuSamplerProduct ? pyramidEntryWords
                                                 : GpuProductCacheLayout::kHeaderWords;
        });
    // In words: the buffer must fit maxBytes.
    const uint64_t firstEntry = uint64_t(pixels) + (pixels & 1u); // entries on 8-byte boundaries
    layout.skipped = fitProductCacheEntries(sizes, firstEntry, maxBytes / 4u);
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
