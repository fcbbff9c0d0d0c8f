// GpuPathTracer::prepareProductCache: the per-pixel camera-vertex product cache's layout
// (product_cache.h), laid out on the CPU and uploaded before the pass that builds the entries.
#include "render/gpu/gpu_path_tracer_impl.h"
#include "render/gpu/product_cache.h"
#include "render/reference/product_cache_pixels.h"

#include "util/log.h"
#include "util/timer.h"

#include <algorithm>
#include <string>

namespace wavelit::render::gpu_tracer {

util::Result<bool> GpuPathTracer::prepareProductCache() {
    util::Timer timer;
    const int width = m_options.width, height = m_options.height;
    if (m_productCacheRowsTraced == 0)
        m_productCacheEntryWords.assign(size_t(width) * size_t(height), 0u);
    const int bandRows = std::max(1, kProductCacheLayoutBandPixels / std::max(width, 1));
    const auto entryWords = gpuProductCacheEntryWords(m_packedSamplerMaterials);
    while (m_productCacheRowsTraced < height) {
        if (m_interrupt && m_interrupt()) {
            m_productCacheLayoutSeconds += timer.seconds();
            return false;
        }
        const int end = std::min(height, m_productCacheRowsTraced + bandRows);
        traceProductCacheRows(*m_scene, *m_bvh, width, height, m_productCacheRowsTraced, end,
                              entryWords, m_productCacheEntryWords);
        m_productCacheRowsTraced = end;
    }
    const uint64_t range = m_context->limits().maxStorageBufferRange;
    const GpuProductCacheLayout layout = layoutGpuProductCache(
        std::move(m_productCacheEntryWords), range > 0 ? range : UINT64_MAX);
    m_productCacheEntryWords = {};
    m_productCacheRowsTraced = 0;
    const size_t bytes = size_t(layout.bytes());
    if (m_productCache.handle() == VK_NULL_HANDLE || m_productCache.size() != bytes) {
        // Before a failed creation the old buffer stays bound; an error ends the render.
        auto buffer = upload(nullptr, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "product cache");
        if (!buffer)
            return buffer.error();
        m_productCache = std::move(buffer.value());
        bindAll(m_productCacheBinding, m_productCache);
    }
    m_productCache.write(layout.offsets.data(), layout.offsets.size() * sizeof(uint32_t));
    ++m_productCacheBuilds;
    m_timings.productCacheBytes = bytes;
    const double seconds = m_productCacheLayoutSeconds + timer.seconds();
    m_productCacheLayoutSeconds = 0.0;
    util::logInfo("product cache: " + std::to_string(layout.entries) + " pixels (" +
                  std::to_string(layout.pyramidEntries) + " with a per-hit pyramid, " +
                  std::to_string(layout.skipped) + " left out), " + std::to_string(bytes) +
                  " bytes, laid out in " + std::to_string(int(seconds * 1000.0)) + " ms");
    return true;
}

} // namespace wavelit::render::gpu_tracer
