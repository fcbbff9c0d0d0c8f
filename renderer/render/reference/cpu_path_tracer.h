// CPU reference path tracer: docs/estimator.md term for term (same PCG32 streams per pixel and
// pass, same draw order, camera, env lookup, surface rules, BRDF plugins, Russian roulette), so
// its mean image and the Vulkan tracer's agree within Monte Carlo noise — and, up to float
// rounding differences between C++ and GLSL, path for path. It is the ground truth of render
// tests, so it favours clarity over speed: one sample per pixel per pass, std::thread workers
// over 16×16 tiles, accumulation in double.
//
// Analytic lights (point, sphere, rect, spot, sun) get next-event estimation at every hit, MIS'd
// with BSDF sampling (light_set.h; docs/estimator.md "Analytic lights"). Direction samplers
// (RenderOptions::sampler, issues 6 and 20): `bsdf`, `env`, `mis`, `wavelet` and `oracle` draw
// the continuation from the material's plugin with (u1, u2), `uniform` and `cosine` from a
// DirectionSampler with (u1, u2, u3); `env`, `mis`, `wavelet` and `oracle` also estimate direct
// env light by next-event estimation from their DirectionSampler (direction_sampler.h,
// docs/estimator.md "Direction samplers"), in the draw order the Vulkan tracer shares; tables held
// by a SamplerTablesCache: built at create() for the materials the scene's objects use, and on
// setScene() rebuilt only where the new scene invalidates them (an object move rebuilds none,
// architecture.md §5). sampleScatter/scatterPdf are the one
// place that draws the next direction and the one pdf the MIS weights of analytic lights use, so
// a light hit by a sampled direction is weighted with the pdf of the sampler actually used.
// `wavelet`'s camera-vertex mixture is cached per pixel across passes, as in the Vulkan tracer
// (cpu_camera_nee.cpp): built in the first pass after a reset, dropped by every reset.
// Not thread-safe as an object (driven by one thread); renderPass uses workers internally.
// samplePixel (one path, term for term) is in cpu_path_tracer_path.cpp, the rest in
// cpu_path_tracer.cpp.
#pragma once

#include "render/reference/cpu_camera.h"
#include "render/lights/cpu_environment.h"
#include "render/sampling/direction_sampler.h"
#include "render/session/integrator.h"
#include "render/lights/light_set.h"
#include "render/reference/path_record.h"
#include "render/session/light_groups.h"
#include "render/session/render_options.h"
#include "render/sampling/sampler_tables_cache.h"
#include "scene/bvh.h"
#include "scene/scene.h"

#include "plugins/brdf.h"
#include "util/hemisphere_sampling.h"

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wavelit::render {

class CpuPathTracer final : public Integrator {
public:
    // threadCount 0 = std::thread::hardware_concurrency(). Errors: sampler not implemented
    // (Unsupported), unknown BRDF plugin in a material (Unsupported, names the material),
    // non-positive image size or negative bounces (Invalid).
    static util::Result<std::unique_ptr<CpuPathTracer>>
    create(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
           const RenderOptions& options, int threadCount = 0);

    util::Status renderPass() override;
    int samplesPerPixel() const override { return m_passes; }
    util::Result<util::ImageRGB> image() override;
    void resetAccumulation() override;
    std::string deviceName() const override;
    IntegratorTimings timings() const override { return m_timings; }
    // Swaps in a new scene and BVH (same options), rebuilding the sampler tables the change
    // invalidates, and restarts accumulation. Errors as create()'s; on error nothing changes.
    util::Status setScene(std::shared_ptr<const scene::Scene> scene,
                          std::shared_ptr<const scene::Bvh> bvh) override;
    // As setScene, with the sampler tables rebuilt by the change set's invalidations (a light or
    // camera edit builds none) instead of by comparing inputs.
    util::Status applyChanges(std::shared_ptr<const scene::Scene> scene,
                              std::shared_ptr<const scene::Bvh> bvh,
                              const scene::ChangeSet& changes) override;
    // Sampler-table builds of the last update (the CPU tracer uploads nothing).
    UpdateCounts lastUpdate() const override { return m_lastUpdate; }
    std::shared_ptr<const DirectionSamplerTables> samplerTables() const override {
        return m_samplerTables;
    }
    SamplerTablesRebuilds samplerRebuilds() const override { return m_samplerCache.rebuilds(); }

    // One path through pixel (x, y) in pass `pass`: the estimator's single-sample radiance.
    // Deterministic: a function of (seed, pass, pixel) only. Public so tests (and GPU-vs-CPU
    // comparisons) can look at individual paths.
    // With `record`, also writes the path down term by term (path_record.h; the outlier tracer).
    // With `groups` (lightGroups().size() entries, overwritten): the same radiance split by the
    // light group of the emitter each term comes from (light_groups.h); they sum to the result.
    glm::vec3 samplePixel(int x, int y, int pass, PathRecord* record = nullptr,
                          glm::vec3* groups = nullptr) const;
    // The scene's light groups (the layers groupImages() returns, and samplePixel's `groups`).
    const LightGroups& lightGroups() const { return m_groups; }
    // With RenderOptions::lightGroups: each layer's mean; without: an empty list.
    util::Result<std::vector<util::ImageRGB>> groupImages() override;

    int threadCount() const { return m_threadCount; }
    // `wavelet`'s per-pixel camera-vertex product cache: how often it was laid out and built
    // (once per reset), its entries, and those its memory budget left out (their pixels use
    // `mis`'s technique at the camera vertex, as the Vulkan tracer's do). Tests and the report.
    uint64_t productCacheBuilds() const { return m_cameraNeeBuilds; }
    size_t productCacheEntries() const { return m_cameraNee.size(); }
    uint64_t productCacheSkipped() const { return m_cameraNeeSkipped; }
    // Test hook: the cache's memory budget in bytes (default 0: a quarter of physical memory);
    // applies from the next reset.
    void setProductCacheBudget(uint64_t bytes) { m_cameraNeeBudget = bytes; }
    // The direction sampler's report (env resolution, per-material choices); empty for `bsdf`.
    std::string samplerReport() const;

    // Test hook: which strategies reach analytic area lights (light_set.h). Renders use Mis; the
    // three must agree in the mean. Changing it does not reset the accumulation.
    void setLightStrategy(LightStrategy strategy) { m_lightStrategy = strategy; }

private:
    // A material resolved once: plugin pointer and parameters, so the hot loop does no lookups.
    // samplerIndex: the material's index in m_samplerTables (-1: no object uses it).
    struct ResolvedMaterial {
        const plugins::Brdf* brdf;
        plugins::BrdfParams params;
        glm::vec3 emission;
        int samplerIndex = -1;
    };

    CpuPathTracer(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
                  const RenderOptions& options, std::vector<ResolvedMaterial> materials,
                  int threadCount);
    // The scene's materials plus the default (last); errors: unknown BRDF plugin.
    static util::Result<std::vector<ResolvedMaterial>> resolveMaterials(const scene::Scene& scene);
    static void setSamplerIndices(std::vector<ResolvedMaterial>& materials,
                                  const std::vector<int>& samplerIndexOfMaterial);
    const ResolvedMaterial& material(float index) const;
    // setScene and applyChanges (`changed`: the change set's invalidations, or nullptr).
    util::Status swapScene(std::shared_ptr<const scene::Scene> scene,
                           std::shared_ptr<const scene::Bvh> bvh,
                           const std::vector<scene::Invalidation>* changed);
    // resetAccumulation's two halves: the sums, and the camera-vertex cache.
    void resetSums();
    void dropCameraNee();

    // The direction-sampling step (local shading frame, solid-angle pdf). `ds` is the vertex's
    // DirectionSampler (nullptr for the `bsdf` kind: the plugin samples with u1, u2, u3 unused);
    // f always comes from the plugin's eval at the drawn direction.
    struct ScatterDraw {
        glm::vec3 wi{0.0f, 0.0f, 1.0f};
        glm::vec3 f{0.0f};
        float pdf = 0.0f;
        bool valid = false;
        const char* technique = "";
    };
    ScatterDraw sampleScatter(const ResolvedMaterial& mat, const util::Frame& frame,
                              const DirectionSampler* ds, const glm::vec3& wo, float u1, float u2,
                              float u3) const;
    // pdf of sampleScatter's draw at local direction wi (the MIS partner of light sampling).
    float scatterPdf(const ResolvedMaterial& mat, const util::Frame& frame,
                     const DirectionSampler* ds, const glm::vec3& wo, const glm::vec3& wi) const;
    // Next-event estimation from `origin` (the offset hit point the continuation ray leaves from):
    // one light chosen by uSelect, sampled with (u1, u2), shadow ray, MIS weight. Radiance
    // toward the viewer, before the path throughput. With `record`, fills its technique, pdf,
    // MIS pdfs, weight, f·cos and radiance (the outlier tracer).
    glm::vec3 nextEvent(const ResolvedMaterial& mat, const util::Frame& frame,
                        const DirectionSampler* ds, const glm::vec3& wo, const glm::vec3& ng, const glm::vec3& origin,
                        float uSelect, float u1, float u2,
                        PathEvent* record = nullptr) const;

    // Next-event estimation of DIRECT environment light (issue 20; env, mis, wavelet, oracle):
    // a direction from the vertex's NEE technique `nee` with (u1, u2, u3) (nullptr: the env
    // technique alone, sampleEnvTechnique), a shadow ray, the env's
    // radiance, MIS-weighted against the BSDF continuation (`env`: weight 1). Radiance toward the
    // viewer before the path throughput; with `events`, also records the term (beta: the
    // throughput, for the record and `mis`'s Russian roulette on the shadow ray, whose coin is
    // u3).
    glm::vec3 envNextEvent(const ResolvedMaterial& mat, const util::Frame& frame,
                           const DirectionSampler* nee, const glm::vec3& wo, const glm::vec3& ng,
                           const glm::vec3& origin, float u1, float u2, float u3,
                           std::vector<PathEvent>* events, int vertex,
                           const glm::vec3& beta) const;

    // `wavelet`'s env NEE technique at a path's camera vertex (depth 0) of pixel (x, y)
    // (cpu_camera_nee.cpp): for a material whose policy forms a product (Product, BsdfLobe), the
    // mixture built at the pixel CENTRE's hit when that hit has the same material, else `mis`'s
    // (the env alone); other materials as at any vertex. Returns the sampler to use: the pixel's
    // cached entry (built in the first pass after a reset, as the Vulkan tracer's
    // product_cache.glsl) or one built into `own`.
    const DirectionSampler* cameraNeeSampler(std::optional<DirectionSampler>& own, int x, int y,
                                             const ResolvedMaterial& mat,
                                             const ShadingPoint& here) const;
    // A pixel's camera-vertex product cache entry: the centre hit's material and, when that
    // material forms a product, the mixture built there.
    struct CameraNeeEntry {
        const ResolvedMaterial* material = nullptr;
        std::optional<DirectionSampler> sampler;
    };
    CameraNeeEntry buildCameraNeeEntry(int x, int y) const;
    bool formsCameraProduct(const ResolvedMaterial& mat) const;
    // Before the first pass after a reset: which pixels get an entry (product_cache_pixels.h);
    // false when the render uses no cache (not `wavelet`, or a black environment).
    bool layoutCameraNeeCache();

    std::shared_ptr<const scene::Scene> m_scene;
    std::shared_ptr<const scene::Bvh> m_bvh;
    RenderOptions m_options;
    std::vector<ResolvedMaterial> m_materials; // Scene::materials order, + the default at the end
    CpuCamera m_camera;
    CpuEnvironment m_environment;
    LightSet m_lights;
    // Direction-sampler tables (nullptr for `bsdf`), from m_samplerCache for the current scene.
    SamplerTablesCache m_samplerCache;
    std::shared_ptr<const DirectionSamplerTables> m_samplerTables;
    LightStrategy m_lightStrategy = LightStrategy::Mis;
    int m_threadCount;
    std::vector<glm::dvec3> m_sum;
    // LightMix: the groups of the current scene (always known: samplePixel's `groups`) and, with
    // RenderOptions::lightGroups, their sums, group-major (group g's pixel p at g·W·H + p).
    LightGroups m_groups;
    std::vector<glm::dvec3> m_groupSum;
    int m_passes = 0;
    // `wavelet`'s per-pixel camera-vertex product cache (cpu_camera_nee.cpp; the Vulkan tracer's
    // twin is render/gpu/product_cache.h): each pixel's index into m_cameraNee (kNoCameraNee:
    // none), laid out and built in the first pass after a reset, read by the later ones. Entries
    // only for pixels whose centre hit forms a product; a worker fills only its tile's pixels.
    static constexpr uint32_t kNoCameraNee = 0xFFFFFFFFu;
    std::vector<uint32_t> m_cameraNeeIndex;
    std::vector<CameraNeeEntry> m_cameraNee;
    bool m_cameraNeeReady = false; // m_cameraNee holds the current scene's entries
    uint64_t m_cameraNeeBuilds = 0;
    uint64_t m_cameraNeeSkipped = 0;
    uint64_t m_cameraNeeBudget = 0; // bytes; 0: a quarter of the machine's memory
    IntegratorTimings m_timings;
    UpdateCounts m_lastUpdate;
};

} // namespace wavelit::render
