#include "render/gpu/product_cache.h"

#include "render/reference/cpu_camera.h"

#include <algorithm>
#include <limits>

namespace wavelit::render {

uint32_t gpuProductCachePyramidWords() {
    return ((1u << (2 * (kGpuMaxProductLevel + 1))) - 1u) / 3u;
}

GpuProductCacheLayout layoutGpuProductCache(const scene::Scene& scene, const scene::Bvh& bvh,
                                            int width, int height,
                                            const std::vector<GpuSamplerMaterial>& samplerMaterials,
                                            uint64_t maxBytes) {
    GpuProductCacheLayout layout;
    const size_t pixels = size_t(width) * size_t(height);
    layout.words.assign(pixels, GpuProductCacheLayout::kNoEntry);
    const CpuCamera camera(scene.camera, width, height);
    const uint32_t pyramidWords = gpuProductCachePyramidWords();
    uint64_t next = pixels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            scene::BvhHit hit;
            // The pixel centre, as the kernel's build pass traces it (jitter 0.5, 0.5).
            if (!scene::intersect(bvh, camera.origin(), camera.direction(x, y, 0.5f, 0.5f), 0.0f,
                                  std::numeric_limits<float>::max(), hit))
                continue;
            // The kernel's material index: min(uint(max(v0.w, 0)), materialCount - 1).
            const float w = bvh.triangles[hit.triangle].v0[3];
            const size_t m = std::min(size_t(std::max(w, 0.0f)), samplerMaterials.size() - 1);
            const GpuSamplerMaterial& sm = samplerMaterials[m];
            if (sm.mode != kGpuSamplerProduct && sm.mode != kGpuSamplerBsdfLobe)
                continue;
            const bool pyramid = sm.mode == kGpuSamplerProduct && sm.precomputedBins == 0;
            const uint64_t size = GpuProductCacheLayout::kHeaderWords + (pyramid ? pyramidWords : 0u);
            if ((next + size) * 4u > maxBytes) {
                ++layout.skipped;
                continue;
            }
            layout.words[size_t(y) * size_t(width) + size_t(x)] = uint32_t(next);
            next += size;
            ++layout.entries;
            layout.pyramidEntries += pyramid ? 1u : 0u;
        }
    layout.words.resize(size_t(next), 0u);
    return layout;
}

} // namespace wavelit::render
