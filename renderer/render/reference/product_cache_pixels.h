// Which pixels get an entry in a tracer's per-pixel camera-vertex product cache (issue 12,
// docs/performance.md "Wavelet pass cost, round 4" and "The CPU tracer's product cache"). Both
// tracers cache the `wavelet` NEE mixture built at a pixel CENTRE's hit (jitter 0.5, 0.5) and
// decide which pixels get one by the same rule, here: the centre ray's hit has a material whose
// policy forms a product (the caller's entrySize says how much an entry of that material takes;
// 0: none, the pixel keeps no entry); when the entries do not all fit a budget, a hashed subset of
// the candidates, spread over the whole image, keeps them (the others use `mis`'s technique at
// their camera vertex: unbiased, only noisier). The Vulkan tracer packs the result into its
// buffer (render/gpu/product_cache.h, units of 4-byte words), the CPU tracer into its entry table
// (cpu_camera_nee.cpp, units of bytes).
#pragma once

#include "scene/bvh.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace wavelit::render {

// Each pixel's entry size (row-major, 0: none) from its centre ray traced on the BVH, rows shared
// among the machine's threads (one ray a pixel: ~0.4 CPU-s at 1600 x 1000). entrySize gets the
// hit triangle's material index as the BVH stores it (v0.w); it must be thread-safe.
std::vector<uint32_t> productCacheEntrySizes(const scene::Scene& scene, const scene::Bvh& bvh,
                                             int width, int height,
                                             const std::function<uint32_t(float)>& entrySize);

// The same for rows [firstRow, endRow) only, into sizes (width x height, row-major): a caller
// that must stay interruptible (the Vulkan tracer's pass) traces the image a band at a time.
void traceProductCacheRows(const scene::Scene& scene, const scene::Bvh& bvh, int width, int height,
                           int firstRow, int endRow,
                           const std::function<uint32_t(float)>& entrySize,
                           std::vector<uint32_t>& sizes);

// Fits the entries into maxUnits (in entrySize's units, with fixedUnits already taken): when
// fixedUnits + the sum of sizes exceeds it, the candidates first in a hashed pixel order keep
// their entry until the budget is full and the rest are set to 0. Returns how many were dropped.
uint64_t fitProductCacheEntries(std::vector<uint32_t>& sizes, uint64_t fixedUnits,
                                uint64_t maxUnits);

} // namespace wavelit::render
