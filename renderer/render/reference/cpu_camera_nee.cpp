// CpuPathTracer's `wavelet` camera-vertex NEE mixture, built at the pixel centre's hit and cached
// per pixel across passes: the estimator and cache of the Vulkan tracer
// (shaders/sampling/product_cache.glsl, render/gpu/product_cache.h; docs/estimator.md "Direction
// samplers", docs/performance.md "The CPU tracer's product cache"). While an image accumulates,
// camera and scene are fixed, so the mixture (~350 BRDF x cos evaluations: the product's 289
// leaf corners and the share rule's tail; a dense 16^2 product: the kernel's,
// ProductBuild::Tracer) is built once per pixel, in the first pass after a reset, instead of on
// every path. Same pixels as the GPU's (product_cache_pixels.h), same mixture, same
// validity rule at a path's camera vertex: the pixel's entry when its centre hit the SAME
// material, else `mis`'s technique (the env alone).
#include "render/reference/cpu_path_tracer.h"

#include "render/reference/cpu_surface.h"
#include "render/reference/product_cache_pixels.h"
#include "render/sampling/product/env_product_tables.h"
#include "util/hemisphere_sampling.h"
#include "wavelet/hierarchical_sampler.h"
#include "util/log.h"
#include "util/timer.h"

#include <unistd.h>

#include <limits>
#include <string>

namespace wavelit::render {
namespace {

// What an entry costs in memory, to fit the cache into its budget before building it: the entry,
// its sampler object, components, description and lobe-refinement closure (kEntryBytes), plus for
// a per-hit product its pyramid's nodes, at most (4^(m+1) - 1) / 3 of them. Measured at 512^2 on
// ring_on_ground (the tracers' m = 4: at most 341 nodes, 6.5 KB estimated): 6.4 KB of memory an
// entry (docs/performance.md "The C++ tracer builds the kernel's product").
constexpr uint32_t kEntryBytes = 1024;

uint32_t productEntryBytes(int productLevel) {
    const uint64_t nodes = ((uint64_t(1) << (2 * (productLevel + 1))) - 1u) / 3u;
    return uint32_t(kEntryBytes + nodes * sizeof(wavelet::HierarchicalSampler::TableNode));
}

// A quarter of the machine's memory (the image buffers may take half: render_limits.h); 0 when
// unknown, i.e. unbounded.
uint64_t defaultBudgetBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) / 4u : 0u;
}

} // namespace

bool CpuPathTracer::formsCameraProduct(const ResolvedMaterial& mat) const {
    if (mat.samplerIndex < 0) return false;
    const MaterialProductTables* tables = m_samplerTables->productTables(size_t(mat.samplerIndex));
    return tables && (tables->policy().mode == ProductMode::Product ||
                      tables->policy().mode == ProductMode::BsdfLobe);
}

CpuPathTracer::CameraNeeEntry CpuPathTracer::buildCameraNeeEntry(int x, int y) const {
    CameraNeeEntry entry;
    // The pixel centre (jitter 0.5, 0.5), as the kernel's cache-building pass traces it.
    const glm::vec3 dir = m_camera.direction(x, y, 0.5f, 0.5f);
    scene::BvhHit hit;
    if (!scene::intersect(*m_bvh, m_camera.origin(), dir, 0.0f, std::numeric_limits<float>::max(),
                          hit))
        return entry;
    const SurfacePoint sp = surfaceAt(*m_bvh, hit, m_camera.origin(), dir);
    const ResolvedMaterial& mat = material(sp.materialIndex);
    entry.material = &mat;
    if (!formsCameraProduct(mat)) return entry;
    const util::Frame frame = util::Frame::fromNormal(sp.shading);
    entry.sampler.emplace(*m_samplerTables, SamplerKind::Wavelet,
                          ShadingPoint{frame.n, frame.t, frame.b, -dir, size_t(mat.samplerIndex)},
                          ProductBuild::Tracer);
    return entry;
}

bool CpuPathTracer::layoutCameraNeeCache() {
    util::Timer timer;
    m_cameraNeeIndex.clear();
    m_cameraNee.clear();
    m_cameraNeeSkipped = 0;
    m_timings.productCacheBytes = 0;
    if (m_options.sampler != SamplerKind::Wavelet || !m_samplerTables ||
        !m_samplerTables->environment().hasLight())
        return false;
    // No material forms a product (all EnvMis, as under the production scenes' sun): no entries,
    // so not even the centre rays.
    bool anyProduct = false;
    for (const ResolvedMaterial& mat : m_materials)
        anyProduct = anyProduct || formsCameraProduct(mat);
    if (!anyProduct) return false;
    std::vector<uint32_t> sizes = productCacheEntrySizes(
        *m_scene, *m_bvh, m_options.width, m_options.height, [&](float index) -> uint32_t {
            const ResolvedMaterial& mat = material(index);
            if (!formsCameraProduct(mat)) return 0u;
            const ProductPolicy& policy =
                m_samplerTables->productTables(size_t(mat.samplerIndex))->policy();
            return policy.mode == ProductMode::Product
                       ? productEntryBytes(tracerProductLevel(policy))
                       : kEntryBytes;
        });
    const uint64_t budget = m_cameraNeeBudget > 0 ? m_cameraNeeBudget : defaultBudgetBytes();
    m_cameraNeeSkipped = fitProductCacheEntries(
        sizes, uint64_t(sizes.size()) * sizeof(uint32_t),
        budget > 0 ? budget : std::numeric_limits<uint64_t>::max());
    m_cameraNeeIndex.assign(sizes.size(), kNoCameraNee);
    uint64_t bytes = uint64_t(sizes.size()) * sizeof(uint32_t);
    uint32_t next = 0;
    for (size_t i = 0; i < sizes.size(); ++i)
        if (sizes[i] != 0u) {
            m_cameraNeeIndex[i] = next++;
            bytes += sizes[i];
        }
    m_cameraNee.resize(next); // the workers build them in their tiles
    ++m_cameraNeeBuilds;
    m_timings.productCacheBytes = bytes;
    util::logInfo("CPU product cache: " + std::to_string(next) + " pixels (" +
                  std::to_string(m_cameraNeeSkipped) + " left out by the " +
                  std::to_string(budget >> 20) + " MiB budget), ~" + std::to_string(bytes >> 20) +
                  " MiB, laid out in " + std::to_string(int(timer.milliseconds())) + " ms");
    return true;
}

const DirectionSampler* CpuPathTracer::cameraNeeSampler(std::optional<DirectionSampler>& own,
                                                        int x, int y, const ResolvedMaterial& mat,
                                                        const ShadingPoint& here) const {
    if (!formsCameraProduct(mat)) {
        own.emplace(*m_samplerTables, SamplerKind::Wavelet, here);
        return &*own;
    }
    if (!m_cameraNeeIndex.empty()) {
        // The cache (its pixel's entry is built before the pixel's first path): a pixel without
        // one hit no such material at its centre, or was left out by the budget.
        const uint32_t i = m_cameraNeeIndex[size_t(y) * size_t(m_options.width) + size_t(x)];
        if (i != kNoCameraNee && m_cameraNee[i].material == &mat && m_cameraNee[i].sampler)
            return &*m_cameraNee[i].sampler;
    } else {
        // No cache laid out (a path traced outside a pass): the same mixture, built for this path.
        CameraNeeEntry built = buildCameraNeeEntry(x, y);
        if (built.material == &mat && built.sampler) {
            own = std::move(built.sampler);
            return &*own;
        }
    }
    // The centre hit another material or nothing (a silhouette): `mis`'s technique.
    own.emplace(*m_samplerTables, SamplerKind::Env, here);
    return &*own;
}

} // namespace wavelit::render
