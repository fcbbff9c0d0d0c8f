// CpuPathTracer::cameraNeeSampler: `wavelet`'s camera-vertex NEE mixture built at the pixel
// centre's hit, the estimator the Vulkan tracer computes from its per-pixel product cache
// (shaders/sampling/product_cache.glsl; docs/estimator.md "Direction samplers").
#include "render/reference/cpu_path_tracer.h"

#include "render/reference/cpu_surface.h"
#include "render/sampling/product/env_product_tables.h"
#include "util/hemisphere_sampling.h"

#include <limits>

namespace wavelit::render {

void CpuPathTracer::cameraNeeSampler(std::optional<DirectionSampler>& ds, int x, int y,
                                     const ResolvedMaterial& mat, const ShadingPoint& here) const {
    const MaterialProductTables* tables = m_samplerTables->productTables(size_t(mat.samplerIndex));
    const bool product = tables && (tables->policy().mode == ProductMode::Product ||
                                    tables->policy().mode == ProductMode::BsdfLobe);
    if (!product) {
        ds.emplace(*m_samplerTables, SamplerKind::Wavelet, here);
        return;
    }
    // The pixel centre (jitter 0.5, 0.5), as the kernel's cache-building pass traces it.
    const glm::vec3 dir = m_camera.direction(x, y, 0.5f, 0.5f);
    scene::BvhHit hit;
    if (scene::intersect(*m_bvh, m_camera.origin(), dir, 0.0f, std::numeric_limits<float>::max(),
                         hit)) {
        const SurfacePoint sp = surfaceAt(*m_bvh, hit, m_camera.origin(), dir);
        if (&material(sp.materialIndex) == &mat) {
            const util::Frame frame = util::Frame::fromNormal(sp.shading);
            ds.emplace(*m_samplerTables, SamplerKind::Wavelet,
                       ShadingPoint{frame.n, frame.t, frame.b, -dir, size_t(mat.samplerIndex)});
            return;
        }
    }
    // The centre hit another material or nothing (a silhouette): `mis`'s technique.
    ds.emplace(*m_samplerTables, SamplerKind::Env, here);
}

} // namespace wavelit::render
