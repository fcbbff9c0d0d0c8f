// GpuPathTracer::prepareProductCache: the per-pixel camera-vertex product cache's layout
// (product_cache.h), laid out on the CPU and uploaded before the pass that builds the entries.
#include "render/gpu/gpu_path_tracer_impl.h"
#include "render/gpu/product_cache.h"

#include "util/log.h"
#include "util/timer.h"

#include <string>

namespace wavelit::render::gpu_tracer {

util::Status GpuPathTracer::prepareProductCache() {
    util::Timer timer;
    const uint64_t range = m_context->limits().maxStorageBufferRange;
    GpuProductCacheLayout layout =
        layoutGpuProductCache(*m_scene, *m_bvh, m_options.width, m_options.height,
                              m_packedSamplerMaterials, range > 0 ? range : UINT64_MAX);
    const size_t bytes = size_t(layout.bytes());
    if (m_productCache.handle() == VK_NULL_HANDLE || m_productCache.size() != bytes) {
        // Before a failed creation the old buffer stays bound; an error ends the render.
        auto buffer = upload(nullptr, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "product cache");
        if (!buffer)
            return buffer.error();
        m_productCache = std::move(buffer.value());
        bindAll(m_productCacheBinding, m_productCache);
    }
    m_productCache.write(layout.words.data(), bytes);
    ++m_productCacheBuilds;
    m_timings.productCacheBytes = bytes;
    util::logInfo("product cache: " + std::to_string(layout.entries) + " pixels (" +
                  std::to_string(layout.pyramidEntries) + " with a per-hit pyramid, " +
                  std::to_string(layout.skipped) + " left out), " + std::to_string(bytes) +
                  " bytes, laid out in " + std::to_string(int(timer.milliseconds())) + " ms");
    return util::okStatus();
}

} // namespace wavelit::render::gpu_tracer
