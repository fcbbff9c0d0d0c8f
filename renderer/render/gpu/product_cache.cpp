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

std::function<uint32_t(float)> gpuProductCacheEntryWords(
    const std::vector<GpuSamplerMaterial>& samplerMaterials) {
    // The kernel's material index: min(uint(max(v0.w, 0)), materialCount - 1).
    return [&samplerMaterials](float w) -> uint32_t {
        const size_t m = std::min(size_t(std::max(w, 0.0f)), samplerMaterials.size() - 1);
        const GpuSamplerMaterial& sm = samplerMaterials[m];
        if (sm.mode == kGpuSamplerProduct)
            return gpuProductCachePyramidEntryWords();
        return sm.mode == kGpuSamplerBsdfLobe ? GpuProductCacheLayout::kHeaderWords : 0u;
    };
}

GpuProductCacheLayout layoutGpuProductCache(std::vector<uint32_t> entryWords, uint64_t maxBytes) {
    static_assert(GpuProductCacheLayout::kHeaderWords % 2 == 0 &&
                  GpuProductCacheLayout::kPyramidAt % 2 == 1);
    GpuProductCacheLayout layout;
    const size_t pixels = entryWords.size();
    const uint64_t firstEntry = uint64_t(pixels) + (pixels & 1u); // entries on 8-byte boundaries
    layout.skipped = fitProductCacheEntries(entryWords, firstEntry, maxBytes / 4u); // in words
    layout.offsets.assign(size_t(firstEntry), GpuProductCacheLayout::kNoEntry);
    uint64_t next = firstEntry;
    for (size_t i = 0; i < pixels; ++i) {
        if (entryWords[i] == 0u)
            continue;
        layout.offsets[i] = uint32_t(next);
        next += entryWords[i];
        ++layout.entries;
        layout.pyramidEntries += entryWords[i] > GpuProductCacheLayout::kHeaderWords ? 1u : 0u;
    }
    layout.words = next;
    return layout;
}

GpuProductCacheLayout layoutGpuProductCache(const scene::Scene& scene, const scene::Bvh& bvh,
                                            int width, int height,
                                            const std::vector<GpuSamplerMaterial>& samplerMaterials,
                                            uint64_t maxBytes) {
    // Which pixels get an entry, by the rule both tracers' caches share (product_cache_pixels.h).
    return layoutGpuProductCache(
        productCacheEntrySizes(scene, bvh, width, height, gpuProductCacheEntryWords(samplerMaterials)),
        maxBytes);
}

} // namespace wavelit::render
