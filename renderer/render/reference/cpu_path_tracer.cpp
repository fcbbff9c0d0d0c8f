#include "render/reference/cpu_path_tracer.h"

#include "render/reference/cpu_surface.h"
#include "render/sampling/sampler_constants.h"
#include "render/session/integrator_factory.h"
#include "util/hemisphere_sampling.h"
#include "util/parallel_for.h"
#include "util/rng.h"
#include "util/timer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace wavelit::render {
namespace {

// Tiles: small enough to balance 2–64 threads on tiny test images, big enough to amortise the
// atomic fetch.
constexpr int kTileSize = 16;

} // namespace

util::Result<std::unique_ptr<CpuPathTracer>>
CpuPathTracer::create(std::shared_ptr<const scene::Scene> scene,
                      std::shared_ptr<const scene::Bvh> bvh, const RenderOptions& options,
                      int threadCount) {
    using util::ErrorKind;
    if (!scene || !bvh)
        return util::makeError(ErrorKind::Invalid, "", "CPU tracer needs a scene and its BVH");
    if (options.width <= 0 || options.height <= 0)
        return util::makeError(ErrorKind::Invalid, "",
                               "image size must be positive, got " + std::to_string(options.width) +
                                   "x" + std::to_string(options.height));
    if (options.bounces < 0)
        return util::makeError(ErrorKind::Invalid, "",
                               "bounces must be >= 0, got " + std::to_string(options.bounces));
    auto materials = resolveMaterials(*scene);
    if (!materials)
        return materials.error();
    // Tables only for the materials some object uses (architecture.md §7).
    SamplerTablesCache cache;
    auto tables = cache.update(*scene, options.sampler);
    if (!tables)
        return tables.error();
    setSamplerIndices(*materials, tables->samplerIndexOfMaterial);
    threadCount = util::threadsOrHardware(threadCount);
    std::unique_ptr<CpuPathTracer> tracer(new CpuPathTracer(
        std::move(scene), std::move(bvh), options, std::move(materials.value()), threadCount));
    tracer->m_samplerCache = std::move(cache);
    tracer->m_samplerTables = std::move(tables->tables);
    return tracer;
}

util::Result<std::vector<CpuPathTracer::ResolvedMaterial>>
CpuPathTracer::resolveMaterials(const scene::Scene& scene) {
    // The default material sits after the scene's: bvh.cpp gives objects whose material id is
    // unknown the index materials.size().
    auto all = resolveSceneMaterials(scene);
    if (!all)
        return all.error();
    std::vector<ResolvedMaterial> materials;
    for (const SceneMaterial& m : *all)
        materials.push_back({m.brdf, scene::brdfParamsOf(m.material),
                             m.material.emission});
    return materials;
}

void CpuPathTracer::setSamplerIndices(std::vector<ResolvedMaterial>& materials,
                                      const std::vector<int>& samplerIndexOfMaterial) {
    for (size_t i = 0; i < materials.size(); ++i)
        materials[i].samplerIndex = samplerIndexOfMaterial[i];
}

util::Status CpuPathTracer::setScene(std::shared_ptr<const scene::Scene> scene,
                                     std::shared_ptr<const scene::Bvh> bvh) {
    return swapScene(std::move(scene), std::move(bvh), nullptr);
}

util::Status CpuPathTracer::applyChanges(std::shared_ptr<const scene::Scene> scene,
                                         std::shared_ptr<const scene::Bvh> bvh,
                                         const scene::ChangeSet& changes) {
    const std::vector<scene::Invalidation> changed = changes.invalidations();
    return swapScene(std::move(scene), std::move(bvh), &changed);
}

util::Status CpuPathTracer::swapScene(std::shared_ptr<const scene::Scene> scene,
                                      std::shared_ptr<const scene::Bvh> bvh,
                                      const std::vector<scene::Invalidation>* changed) {
    using util::ErrorKind;
    if (!scene || !bvh)
        return util::makeError(ErrorKind::Invalid, "", "CPU tracer needs a scene and its BVH");
    // A scene the tracer cannot render (unknown BRDF) leaves it, and its cache, as they were.
    auto materials = resolveMaterials(*scene);
    if (!materials)
        return materials.error();
    const SamplerTablesRebuilds before = m_samplerCache.rebuilds();
    auto tables = m_samplerCache.update(*scene, m_options.sampler, changed);
    if (!tables)
        return tables.error();
    setSamplerIndices(*materials, tables->samplerIndexOfMaterial);
    // The camera-vertex cache depends on the camera, the geometry (the centre hits), the
    // materials and the sampler tables; an edit of lights or of the environment that left the
    // tables as they were (its intensity: tablesEnvironment) keeps it, with the same BVH and
    // tables, and the materials it points into (equal: no material was edited).
    using scene::FactorKind;
    const bool keepCameraNee =
        changed && scene::onlyFactors(*changed, {FactorKind::Light, FactorKind::Environment}) &&
        bvh == m_bvh && tables->tables == m_samplerTables;
    m_scene = std::move(scene);
    m_bvh = std::move(bvh);
    if (!keepCameraNee)
        m_materials = std::move(materials.value());
    // Camera, environment view and lights are a few floats each: rebuilt always (no uploads).
    m_camera = CpuCamera(m_scene->camera, m_options.width, m_options.height);
    m_environment = CpuEnvironment(m_scene->lighting.environment);
    m_lights = LightSet(m_scene->lighting.lights);
    m_groups = lightGroupsOf(*m_scene);
    m_groupSum.assign(m_options.lightGroups ? m_groups.size() * m_sum.size() : 0, glm::dvec3(0.0));
    m_samplerTables = std::move(tables->tables);
    m_timings.bvhBuildSeconds = m_bvh->buildSeconds;
    const SamplerTablesRebuilds& after = m_samplerCache.rebuilds();
    m_lastUpdate = UpdateCounts{};
    m_lastUpdate.samplerTableBuilds = (after.environmentBuilds - before.environmentBuilds) +
                                      (after.materialBuilds - before.materialBuilds);
    m_lastUpdate.samplerTablesTurned = after.environmentRotations - before.environmentRotations;
    resetSums();
    if (!keepCameraNee)
        dropCameraNee();
    return util::okStatus();
}

CpuPathTracer::CpuPathTracer(std::shared_ptr<const scene::Scene> scene,
                             std::shared_ptr<const scene::Bvh> bvh, const RenderOptions& options,
                             std::vector<ResolvedMaterial> materials, int threadCount)
    : m_scene(std::move(scene)), m_bvh(std::move(bvh)), m_options(options),
      m_materials(std::move(materials)),
      m_camera(m_scene->camera, options.width, options.height),
      m_environment(m_scene->lighting.environment), m_lights(m_scene->lighting.lights),
      m_threadCount(threadCount),
      m_sum(size_t(options.width) * size_t(options.height), glm::dvec3(0.0)),
      m_groups(lightGroupsOf(*m_scene)) {
    m_timings.bvhBuildSeconds = m_bvh->buildSeconds;
    // Layers only when asked for (architecture.md §7: model only what a render needs).
    if (options.lightGroups) m_groupSum.assign(m_groups.size() * m_sum.size(), glm::dvec3(0.0));
}

const CpuPathTracer::ResolvedMaterial& CpuPathTracer::material(float index) const {
    size_t i = index >= 0.0f ? size_t(index) : m_materials.size() - 1;
    return m_materials[std::min(i, m_materials.size() - 1)];
}

CpuPathTracer::ScatterDraw CpuPathTracer::sampleScatter(const ResolvedMaterial& mat,
                                                        const util::Frame& frame,
                                                        const DirectionSampler* ds,
                                                        const glm::vec3& wo, float u1, float u2,
                                                        float u3) const {
    if (!ds) {
        const plugins::BrdfSample s = mat.brdf->sample(mat.params, wo, u1, u2);
        return ScatterDraw{s.wi, s.f, s.pdf, s.valid, "bsdf"};
    }
    // The estimator divides by the pdf of what was drawn (the mixture's, architecture.md §4).
    const DirectionSample d = ds->sample(u1, u2, u3);
    if (!d.valid)
        return ScatterDraw{};
    const glm::vec3 wi = frame.toLocal(d.wi);
    return ScatterDraw{wi, mat.brdf->eval(mat.params, wo, wi), d.pdf, true, d.technique};
}

float CpuPathTracer::scatterPdf(const ResolvedMaterial& mat, const util::Frame& frame,
                                const DirectionSampler* ds, const glm::vec3& wo,
                                const glm::vec3& wi) const {
    if (!ds)
        return mat.brdf->pdf(mat.params, wo, wi);
    return ds->pdf(frame.toWorld(wi));
}

std::string CpuPathTracer::samplerReport() const {
    return m_samplerTables ? m_samplerTables->report() : std::string();
}

glm::vec3 CpuPathTracer::nextEvent(const ResolvedMaterial& mat, const util::Frame& frame,
                                   const DirectionSampler* ds, const glm::vec3& wo, const glm::vec3& ng,
                                   const glm::vec3& origin, float uSelect, float u1,
                                   float u2, PathEvent* record) const {
    const LightSampler& light = m_lights.light(m_lights.select(uSelect));
    if (m_lightStrategy == LightStrategy::BsdfOnly && !light.isDelta()) return glm::vec3(0.0f);
    const LightSample ls = light.sample(origin, u1, u2);
    if (!ls.valid || !(ls.pdf > 0.0f)) return glm::vec3(0.0f);
    // The BSDF strategy ends paths below the true surface; light sampling must agree.
    if (glm::dot(ls.wi, ng) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 wi = frame.toLocal(ls.wi);
    if (wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 f = mat.brdf->eval(mat.params, wo, wi);
    if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
    if (scene::occluded(*m_bvh, origin, ls.wi, 0.0f,
                        std::min(ls.distance, std::numeric_limits<float>::max())))
        return glm::vec3(0.0f);
    const float bsdfPdf = ls.delta ? 0.0f : scatterPdf(mat, frame, ds, wo, wi);
    const float w = m_lights.lightWeight(light, ls.pdf, bsdfPdf, m_lightStrategy);
    if (record) {
        record->technique = "light " + std::to_string(m_lights.select(uSelect));
        record->pdf = ls.pdf * m_lights.selectionProbability();
        record->misPdfs = {{"light (x selection)", record->pdf}, {"continuation", bsdfPdf}};
        record->weight = w;
        record->fcos = f * wi.z;
        record->radiance = ls.value;
    }
    return f * ls.value * (wi.z * w / (ls.pdf * m_lights.selectionProbability()));
}

glm::vec3 CpuPathTracer::envNextEvent(const ResolvedMaterial& mat, const util::Frame& frame,
                                      const DirectionSampler* nee, const glm::vec3& wo,
                                      const glm::vec3& ng, const glm::vec3& origin, float u1,
                                      float u2, float u3, std::vector<PathEvent>* events,
                                      int vertex, const glm::vec3& beta) const {
    const SamplerEnvironment& env = m_samplerTables->environment();
    const DirectionSample d = nee ? nee->sample(u1, u2, u3) : sampleEnvTechnique(env, u1, u2);
    if (!d.valid) return glm::vec3(0.0f);
    // The continuation ends paths below the true surface or the shading hemisphere: NEE agrees.
    if (glm::dot(d.wi, ng) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 wi = frame.toLocal(d.wi);
    if (wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 f = mat.brdf->eval(mat.params, wo, wi);
    if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
    // `env`: light sampling alone; the others: power heuristic against the BSDF continuation.
    const float bsdfPdf =
        m_options.sampler == SamplerKind::Env ? 0.0f : mat.brdf->pdf(mat.params, wo, wi);
    const float w = m_options.sampler == SamplerKind::Env ? 1.0f : powerWeight(d.pdf, bsdfPdf);
    float scale = wi.z * w / d.pdf;
    // `mis`'s Russian roulette on the shadow ray (sampler_constants.h misEnvRoulette; env_nee.glsl
    // is the twin) wherever the NEE is `mis`'s technique: `mis`, and `wavelet` past its product
    // vertices and under the EnvMis policy. u3 its coin: the env technique alone draws no
    // technique with it. c from the env's shape (its effective solid angle), not its intensity.
    if (m_options.sampler != SamplerKind::Env && (!nee || nee->envTechniqueOnly())) {
        const glm::vec3 bf = beta * f;
        const float c = misEnvRoulette(env.effectiveSolidAngle());
        const float p = std::max(bf.r, std::max(bf.g, bf.b)) * wi.z * w / c;
        if (p < 1.0f) {
            if (!(u3 < p)) return glm::vec3(0.0f);
            scale /= p;
        }
    }
    if (scene::occluded(*m_bvh, origin, d.wi, 0.0f, std::numeric_limits<float>::max()))
        return glm::vec3(0.0f);
    // The texel whose pdf the draw read (SamplerEnvironment::equirect is this lookup's twin).
    const glm::vec3 Le =
        d.envUv.x >= 0.0f ? m_environment.radianceAt(d.envUv) : m_environment.radiance(d.wi);
    const glm::vec3 value = f * Le * scale;
    if (events && value != glm::vec3(0.0f)) {
        PathEvent e;
        e.vertex = vertex;
        e.kind = "env-nee";
        e.technique = d.technique;
        e.pdf = d.pdf;
        const std::vector<ComponentPdf> components =
            nee ? nee->componentPdfs(d.wi)
                : std::vector<ComponentPdf>{{"env", 1.0, env.pdfWorld(d.wi)}};
        for (const ComponentPdf& c : components) {
            e.misPdfs.push_back({std::string(c.technique), c.pdf});
            e.misPdfs.push_back({"share:" + std::string(c.technique), c.weight});
        }
        e.misPdfs.push_back({"nee", d.pdf});
        e.misPdfs.push_back({"continuation", bsdfPdf});
        e.weight = w;
        e.fcos = f * wi.z;
        e.radiance = Le;
        e.throughput = beta;
        e.contribution = beta * value;
        events->push_back(std::move(e));
    }
    return value;
}

util::Status CpuPathTracer::renderPass() {
    util::Timer timer;
    const int w = m_options.width, h = m_options.height;
    const int tilesX = (w + kTileSize - 1) / kTileSize, tilesY = (h + kTileSize - 1) / kTileSize;
    const int tiles = tilesX * tilesY;
    const int pass = m_options.firstPass + m_passes;
    std::atomic<int> next{0};
    const size_t pixels = m_sum.size();
    const size_t groupCount = m_groupSum.empty() ? 0 : m_groups.size();
    // `wavelet`: the first pass after a reset lays out the camera-vertex product cache and builds
    // each entry in its pixel's tile, just before the pixel's path (cpu_camera_nee.cpp).
    const bool buildCache = !m_cameraNeeReady && layoutCameraNeeCache();
    // Workers write disjoint pixels of m_sum (and of each group's layer, and of the cache): no
    // locking.
    auto worker = [&] {
        std::vector<glm::vec3> groups(groupCount);
        glm::vec3* splat = groupCount ? groups.data() : nullptr;
        for (int tile = next++; tile < tiles; tile = next++) {
            int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
            for (int y = y0; y < std::min(y0 + kTileSize, h); ++y)
                for (int x = x0; x < std::min(x0 + kTileSize, w); ++x) {
                    const size_t p = size_t(y) * size_t(w) + size_t(x);
                    if (buildCache && m_cameraNeeIndex[p] != kNoCameraNee)
                        m_cameraNee[m_cameraNeeIndex[p]] = buildCameraNeeEntry(x, y);
                    m_sum[p] += glm::dvec3(samplePixel(x, y, pass, nullptr, splat));
                    for (size_t g = 0; g < groupCount; ++g)
                        m_groupSum[g * pixels + p] += glm::dvec3(groups[g]);
                }
        }
    };
    // The calling thread is worker 0.
    util::runOnWorkers(size_t(std::max(1, std::min(m_threadCount, tiles))), [&](size_t) { worker(); });
    m_cameraNeeReady = true; // built, or not used by this render
    ++m_passes;
    m_timings.passSeconds += timer.seconds();
    return util::okStatus();
}

util::Result<util::ImageRGB> CpuPathTracer::image() {
    util::ImageRGB img(m_options.width, m_options.height);
    if (m_passes == 0) return img;
    const double inv = 1.0 / m_passes;
    for (size_t i = 0; i < m_sum.size(); ++i) img.pixels[i] = glm::vec3(m_sum[i] * inv);
    return img;
}

util::Result<std::vector<util::ImageRGB>> CpuPathTracer::groupImages() {
    std::vector<util::ImageRGB> layers;
    if (m_groupSum.empty()) return layers;
    const size_t pixels = m_sum.size();
    const double inv = m_passes > 0 ? 1.0 / m_passes : 0.0;
    for (size_t g = 0; g < m_groups.size(); ++g) {
        util::ImageRGB img(m_options.width, m_options.height);
        for (size_t p = 0; p < pixels; ++p)
            img.pixels[p] = glm::vec3(m_groupSum[g * pixels + p] * inv);
        layers.push_back(std::move(img));
    }
    return layers;
}

void CpuPathTracer::resetAccumulation() {
    resetSums();
    dropCameraNee();
}

void CpuPathTracer::resetSums() {
    std::fill(m_sum.begin(), m_sum.end(), glm::dvec3(0.0));
    std::fill(m_groupSum.begin(), m_groupSum.end(), glm::dvec3(0.0));
    m_passes = 0;
    m_timings.passSeconds = 0.0;
}

void CpuPathTracer::dropCameraNee() {
    // A scene, camera or option change (a light edit aside, swapScene): the cached camera-vertex
    // products (built for the old scene's tables and centre hits) are dropped and rebuilt by the
    // next pass.
    m_cameraNeeReady = false;
    m_cameraNeeIndex.clear();
    m_cameraNee.clear();
}

std::string CpuPathTracer::deviceName() const {
    return "CPU reference (" + std::to_string(m_threadCount) + " threads)";
}

util::Result<std::unique_ptr<Integrator>>
createCpuPathTracer(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
                    const RenderOptions& options) {
    auto tracer = CpuPathTracer::create(std::move(scene), std::move(bvh), options);
    if (!tracer) return tracer.error();
    return std::unique_ptr<Integrator>(std::move(tracer.value()));
}

} // namespace wavelit::render
