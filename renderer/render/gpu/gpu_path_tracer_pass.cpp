#include "render/gpu/gpu_path_tracer_impl.h"

#include "util/path_sampler.h"
#include "util/timer.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace wavelit::render::gpu_tracer {

util::Status GpuPathTracer::renderPass() {
    if (m_productCacheCompiled && !m_productCacheReady && !m_productCacheBuilding) {
        auto prepared = prepareProductCache();
        if (!prepared)
            return prepared.error();
        if (!prepared.value())
            return util::okStatus(); // interrupted: the next call resumes the layout
        m_productCacheBuilding = true;
    }
    const PassPush push{util::PathSampler::seedKey(m_options.seed),
                        uint32_t(m_options.firstPass + m_passes)};
    const PassTiles tiles = passTiles();
    // Until a piece has been timed, a small first piece: 4 tiles (1024 pixels) take ~45 ms with
    // `wavelet` on lavapipe under load (a 1600x1000 pass took 71 s), the slowest sampler but the
    // oracle. Pieces at most double from one to the next.
    constexpr uint32_t kFirstPieceTiles = 4;
    while (m_nextTile < tiles.count) {
        if (m_interrupt && m_interrupt())
            return util::okStatus(); // unfinished: the next call resumes at m_nextTile
        uint32_t count = kFirstPieceTiles;
        if (m_secondsPerTile > 0.0)
            count = uint32_t(std::clamp(kGpuPassPieceSeconds / m_secondsPerTile, 1.0,
                                        2.0 * double(std::max(m_lastPieceTiles, kFirstPieceTiles))));
        count = std::min(count, tiles.count - m_nextTile);
        util::Timer timer;
        if (auto status = dispatchPiece(tiles, m_nextTile, count, push); !status)
            return describePassError(status.error(), m_context->deviceName());
        const double seconds = timer.seconds();
        const double perTile = seconds / double(count);
        m_secondsPerTile = m_secondsPerTile > 0.0 ? 0.5 * (m_secondsPerTile + perTile) : perTile;
        m_lastPieceTiles = count;
        m_passElapsed += seconds;
        m_nextTile += count;
    }
    m_nextTile = 0;
    if (m_productCacheBuilding) {
        m_productCacheBuilding = false;
        m_productCacheReady = true;
    }
    ++m_passes;
    m_timings.passSeconds += m_passElapsed;
    m_passElapsed = 0.0;
    return util::okStatus();
}

GpuPathTracer::PassTiles GpuPathTracer::passTiles() const {
    PassTiles t;
    t.groupsX = (uint32_t(m_options.width) + kWorkgroupX - 1) / kWorkgroupX;
    t.groupsY = (uint32_t(m_options.height) + kWorkgroupY - 1) / kWorkgroupY;
    t.tilesX = (t.groupsX + kTileGroups - 1) / kTileGroups;
    t.count = t.tilesX * ((t.groupsY + kTileGroups - 1) / kTileGroups);
    // A stride near count / golden ratio that is coprime with count visits every tile once.
    t.stride = std::max<uint32_t>(1, uint32_t(double(t.count) * 0.6180339887));
    while (std::gcd(t.stride, t.count) != 1)
        ++t.stride;
    return t;
}

util::Status GpuPathTracer::dispatchPiece(const PassTiles& tiles, uint32_t first, uint32_t count,
                                          const PassPush& push) {
    std::vector<vk::DispatchRegion> regions;
    regions.reserve(count);
    for (uint32_t i = first; i < first + count; ++i) {
        const uint32_t tile = uint32_t((uint64_t(i) * tiles.stride) % tiles.count);
        const uint32_t x = (tile % tiles.tilesX) * kTileGroups;
        const uint32_t y = (tile / tiles.tilesX) * kTileGroups;
        regions.push_back({x, y, std::min(kTileGroups, tiles.groupsX - x),
                           std::min(kTileGroups, tiles.groupsY - y)});
    }
    return m_runner->run([&](VkCommandBuffer cmd) {
        if (m_productCacheBuilding) { // the piece's cache entries first (m_cacheKernel)
            m_cacheKernel.dispatchRegions(cmd, regions, &push);
            vk::computeToComputeAndHostBarrier(cmd);
        }
        m_kernel.dispatchRegions(cmd, regions, &push);
        vk::computeToComputeAndHostBarrier(cmd);
    });
}

util::Result<util::ImageRGB> GpuPathTracer::image() {
    util::ImageRGB img(m_options.width, m_options.height);
    if (m_passes == 0)
        return img;
    std::vector<float> sums(img.pixels.size() * 4);
    m_accumulation.read(sums.data(), sums.size() * sizeof(float));
    float inv = 1.0f / float(m_passes);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = glm::vec3(sums[4 * i], sums[4 * i + 1], sums[4 * i + 2]) * inv;
    return img;
}

void GpuPathTracer::resetAccumulation() {
    // renderPass waits for its fence, so no dispatch is in flight here.
    m_accumulation.fill(0);
    if (m_groupLayers.handle() != VK_NULL_HANDLE) m_groupLayers.fill(0);
    m_passes = 0;
    m_nextTile = 0; // an unfinished pass is dropped with the sums it had added
    // Every scene or camera change resets: the cached camera-vertex products are rebuilt (a
    // light-only edit keeps them: applyChanges).
    m_productCacheReady = false;
    m_productCacheBuilding = false;
    m_productCacheRowsTraced = 0; // a layout in progress is for the old scene or camera
    m_productCacheLayoutSeconds = 0.0;
    m_passElapsed = 0.0;
    m_timings.passSeconds = 0.0;
}

} // namespace wavelit::render::gpu_tracer
