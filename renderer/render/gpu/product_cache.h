// The per-pixel cache of the camera vertex's `wavelet` NEE mixture (issue 12, docs/performance.md
// "Wavelet pass cost, round 4"; shaders/sampling/product_cache.glsl reads and fills it). The
// driver lays the buffer out on the CPU: which pixels get an entry (their centre ray's hit, traced
// on the CPU BVH, has a material whose `wavelet` policy forms a product: mode Product or
// BsdfLobe) and where each entry starts; the first pass after a reset fills the entries on the
// device, later passes read them. Only those pixels take memory: a header of kHeaderWords words,
// and for a per-hit product (mode Product) one pad word and its
// pyramid's (4^(m+1) - 1) / 3 floats, m = kGpuMaxProductLevel (341 floats, 1464 bytes an entry in
// all). The shader reads and writes entries through the buffer's u64 view (two words a load on
// lavapipe, docs/performance.md "The product cache and product tables through u64 views"), so:
// the pixels' offset words are padded to an even count, every entry starts at an even word and
// has an even size, and a pyramid starts at an odd word (kPyramidAt), which puts each pair of
// sibling cells (levels >= 1 start at the odd (4^l - 1) / 3) on an 8-byte boundary.
#pragma once

#include "render/gpu/gpu_sampler_data.h"
#include "scene/bvh.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace wavelit::render {

struct GpuProductCacheLayout {
    static constexpr uint32_t kNoEntry = 0xFFFFFFFFu;
    static constexpr uint32_t kHeaderWords = 24;
    static constexpr uint32_t kPyramidAt = kHeaderWords + 1; // an entry's pyramid: odd
    // The buffer's head: [0, pixels) each pixel's entry offset in words (kNoEntry: none), padded
    // to an even count. Only the head is uploaded: the device writes every entry word it reads
    // (pcBuild) before the pass's trace reads it, so the entries' space needs no contents.
    std::vector<uint32_t> offsets;
    uint64_t words = 0;          // the whole buffer: the head and the entries
    uint64_t entries = 0;        // pixels with an entry
    uint64_t pyramidEntries = 0; // of which hold a pyramid
    uint64_t skipped = 0;        // pixels left without one: the buffer would exceed maxBytes
    uint64_t bytes() const { return words * 4u; }
};

// The words a per-hit product's pyramid takes in an entry (an odd count).
uint32_t gpuProductCachePyramidWords();
// The words of an entry with a pyramid: kPyramidAt + the pyramid (an even count).
uint32_t gpuProductCachePyramidEntryWords();

// The words of the entry a centre hit on material index `w` (the BVH's v0.w) takes: 0 (none)
// unless its policy forms a product. samplerMaterials: the packed sampler materials
// (GpuSamplerData::materials, one per GPU material index); it must outlive the function.
std::function<uint32_t(float)> gpuProductCacheEntryWords(
    const std::vector<GpuSamplerMaterial>& samplerMaterials);

// Lays out the cache from each pixel's entry words (row-major, traceProductCacheRows with
// gpuProductCacheEntryWords). maxBytes bounds the buffer (the device's storage-buffer range):
// when not every entry fits, a hashed subset of the pixels, spread over the whole image, gets one;
// the others use `mis`'s technique at their camera vertex (still unbiased, only noisier).
GpuProductCacheLayout layoutGpuProductCache(std::vector<uint32_t> entryWords, uint64_t maxBytes);

// The same for the scene's camera at width x height, its centre rays traced at once.
GpuProductCacheLayout layoutGpuProductCache(const scene::Scene& scene, const scene::Bvh& bvh,
                                            int width, int height,
                                            const std::vector<GpuSamplerMaterial>& samplerMaterials,
                                            uint64_t maxBytes);

} // namespace wavelit::render
