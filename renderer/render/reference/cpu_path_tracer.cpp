#include "render/reference/cpu_path_tracer.h"

#include "render/reference/cpu_surface.h"
#include "render/session/integrator_factory.h"
#include "util/hemisphere_sampling.h"
#include "util/rng.h"
#include "util/timer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace wavelit::render {
namespace {

// docs/estimator.md constants, shared with shaders/path_tracer.comp.
constexpr uint64_t kPassStride = 0x9E3779B97F4A7C15ULL; // pass → seed scramble (golden ratio)
constexpr float kRayOffset = 1e-4f;                      // × max(1, |hit|): scale-aware epsilon
constexpr float kMinContinueProbability = 0.05f;         // Russian roulette floor of q's complement
constexpr int kRussianRouletteDepth = 2;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Tiles: small enough to balance 2–64 threads on tiny test images, big enough to amortise the
// atomic fetch.
constexpr int kTileSize = 16;

// docs/estimator.md: power(a, b) = a > 0 ? 1 / (1 + (b/a)^2) : 0 (lights.glsl's twin).
float powerWeight(float a, float b) {
    if (!(a > 0.0f)) return 0.0f;
    const float r = b / a;
    return 1.0f / (1.0f + r * r);
}

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
    if (threadCount <= 0) threadCount = int(std::max(1u, std::thread::hardware_concurrency()));
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
        materials.push_back({m.brdf, plugins::BrdfParams{m.material.baseColor, m.material.roughness},
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
    using util::ErrorKind;
    if (!scene || !bvh)
        return util::makeError(ErrorKind::Invalid, "", "CPU tracer needs a scene and its BVH");
    // A scene the tracer cannot render (unknown BRDF) leaves it, and its cache, as they were.
    auto materials = resolveMaterials(*scene);
    if (!materials)
        return materials.error();
    auto tables = m_samplerCache.update(*scene, m_options.sampler);
    if (!tables)
        return tables.error();
    setSamplerIndices(*materials, tables->samplerIndexOfMaterial);
    m_scene = std::move(scene);
    m_bvh = std::move(bvh);
    m_materials = std::move(materials.value());
    m_camera = CpuCamera(m_scene->camera, m_options.width, m_options.height);
    m_environment = CpuEnvironment(m_scene->lighting.environment);
    m_lights = LightSet(m_scene->lighting.lights);
    m_samplerTables = std::move(tables->tables);
    m_timings.bvhBuildSeconds = m_bvh->buildSeconds;
    resetAccumulation();
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
      m_sum(size_t(options.width) * size_t(options.height), glm::dvec3(0.0)) {
    m_timings.bvhBuildSeconds = m_bvh->buildSeconds;
}

const CpuPathTracer::ResolvedMaterial& CpuPathTracer::material(float index) const {
    size_t i = index >= 0.0f ? size_t(index) : m_materials.size() - 1;
    return m_materials[std::min(i, m_materials.size() - 1)];
}

glm::vec3 CpuPathTracer::samplePixel(int x, int y, int pass, PathRecord* record) const {
    const uint64_t pixelIndex = uint64_t(y) * uint64_t(m_options.width) + uint64_t(x);
    util::Pcg32 rng(m_options.seed ^ (uint64_t(pass) * kPassStride), pixelIndex);
    // Draws are separate statements: C++ leaves the order of function arguments unspecified,
    // and the draw order is part of the estimator.
    const float jx = rng.nextFloat();
    const float jy = rng.nextFloat();

    glm::vec3 origin = m_camera.origin();
    glm::vec3 dir = m_camera.direction(x, y, jx, jy);
    glm::vec3 L(0.0f), beta(1.0f);
    float scatterPdfOfDir = 0.0f; // solid-angle pdf with which the last vertex drew `dir`
    const SamplerKind kind = m_options.sampler;
    const bool envNee = samplerHasEnvNee(kind);
    const bool lit = m_samplerTables && m_samplerTables->environment().hasLight();
    // The env NEE technique of the vertex that drew `dir` (issue 20), kept so that env light the
    // continuation finds is MIS-weighted against it; empty: that vertex did no env NEE.
    std::optional<DirectionSampler> neeOfDir;
    if (record) {
        *record = PathRecord{};
        record->x = x;
        record->y = y;
        record->pass = pass;
    }
    // Path record helpers (no-ops without a record).
    std::string techniqueOfDir = "camera";
    glm::vec3 fcosOfDir(1.0f), betaBeforeDir(1.0f);
    auto addEvent = [&](int vertex, const char* eventKind, const std::string& technique,
                        double pdf, std::vector<PathPdf> pdfs, double weight, glm::vec3 fcos,
                        glm::vec3 radiance, glm::vec3 throughput, glm::vec3 contribution) {
        if (!record || contribution == glm::vec3(0.0f)) return;
        record->events.push_back(PathEvent{vertex, eventKind, technique, pdf, std::move(pdfs),
                                           weight, fcos, radiance, throughput, contribution});
    };
    for (int depth = 0;; ++depth) {
        const int from = depth - 1; // the vertex that drew `dir`
        scene::BvhHit hit;
        const bool found =
            scene::intersect(*m_bvh, origin, dir, 0.0f, std::numeric_limits<float>::max(), hit);
        // Analytic lights crossed before the surface (or the sun, when the ray escapes).
        if (!m_lights.empty()) {
            const glm::vec3 e = m_lights.emissionAlongRay(origin, dir, found ? hit.t : kInfinity,
                                                          scatterPdfOfDir, depth == 0,
                                                          m_lightStrategy);
            L += beta * e;
            addEvent(from, "light-hit", techniqueOfDir, scatterPdfOfDir, {}, 1.0, fcosOfDir, e,
                     betaBeforeDir, beta * e);
        }
        if (!found) {
            // Direct env light was estimated at the previous vertex by NEE: weight the
            // continuation's find against it (`env`: NEE alone, so 0).
            float w = 1.0f, neePdf = 0.0f;
            if (neeOfDir) {
                neePdf = neeOfDir->pdf(dir);
                w = kind == SamplerKind::Env ? 0.0f : powerWeight(scatterPdfOfDir, neePdf);
            }
            const glm::vec3 e = m_environment.radiance(dir);
            L += beta * (w * e);
            if (record)
                addEvent(from, "env-escape", techniqueOfDir, scatterPdfOfDir,
                         {{"continuation", scatterPdfOfDir}, {"nee", neePdf}}, w, fcosOfDir, e,
                         betaBeforeDir, beta * (w * e));
            break;
        }
        const SurfacePoint sp = surfaceAt(*m_bvh, hit, origin, dir);
        const ResolvedMaterial& mat = material(sp.materialIndex);
        const glm::vec3& ng = sp.geometric;
        const util::Frame frame = util::Frame::fromNormal(sp.shading);
        const glm::vec3 wo = frame.toLocal(-dir);
        L += beta * mat.emission;
        addEvent(from, "emission", techniqueOfDir, scatterPdfOfDir, {}, 1.0, fcosOfDir,
                 mat.emission, betaBeforeDir, beta * mat.emission);
        PathVertex* vertex = nullptr;
        if (record) {
            record->vertices.push_back(PathVertex{});
            vertex = &record->vertices.back();
            vertex->depth = depth;
            const size_t mi = std::min(size_t(std::max(0.0f, sp.materialIndex)),
                                       m_materials.size() - 1);
            vertex->material = mi < m_scene->materials.size() ? m_scene->materials[mi].name
                                                              : std::string("(default)");
            vertex->position = sp.position;
            vertex->throughputIn = beta;
        }
        if (depth == m_options.bounces) {
            if (vertex) vertex->end = "bounce limit";
            break;
        }
        // The vertex's direction sampler: for uniform/cosine it draws the continuation (and its
        // pdf weights the analytic lights); for env/mis/wavelet/oracle it is the env NEE
        // technique (only over an env with light) and the continuation is the plugin's BSDF
        // sample. `bsdf`: none.
        std::optional<DirectionSampler> ds;
        if (m_samplerTables && mat.samplerIndex >= 0 &&
            (continuationFromSampler(kind) || (envNee && lit)))
            ds.emplace(*m_samplerTables, vertexSamplerKind(kind),
                       ShadingPoint{frame.n, frame.t, frame.b, -dir, size_t(mat.samplerIndex)});
        const DirectionSampler* sampler = ds && continuationFromSampler(kind) ? &*ds : nullptr;
        const DirectionSampler* neeSampler = ds && envNee ? &*ds : nullptr;

        // Lights are sampled from the point the continuation ray leaves from, so both MIS
        // strategies evaluate their pdfs at the same point.
        const glm::vec3 next =
            sp.position + ng * (kRayOffset * std::max(1.0f, glm::length(sp.position)));
        if (!m_lights.empty()) {
            const float uSelect = rng.nextFloat();
            const float ul1 = rng.nextFloat();
            const float ul2 = rng.nextFloat();
            PathEvent lightEvent;
            const glm::vec3 e = nextEvent(mat, frame, sampler, wo, ng, next, uSelect, ul1, ul2,
                                          vertex ? &lightEvent : nullptr);
            L += beta * e;
            addEvent(depth, "light-nee", lightEvent.technique, lightEvent.pdf,
                     std::move(lightEvent.misPdfs), lightEvent.weight, lightEvent.fcos,
                     lightEvent.radiance, beta, beta * e);
        }

        if (envNee) {
            // Drawn for every scattering vertex of these kinds, used where the vertex has an env
            // NEE technique (docs/estimator.md "Random numbers").
            const float ue1 = rng.nextFloat();
            const float ue2 = rng.nextFloat();
            const float ue3 = rng.nextFloat();
            if (neeSampler) {
                const glm::vec3 e =
                    envNextEvent(mat, frame, *neeSampler, wo, ng, next, ue1, ue2, ue3,
                                 vertex ? &record->events : nullptr, depth, beta);
                L += beta * e;
            }
        }

        const float u1 = rng.nextFloat();
        const float u2 = rng.nextFloat();
        // The technique choice of a DirectionSampler mixture: drawn only when one draws the
        // continuation (uniform, cosine), the draw order the Vulkan tracer shares
        // (docs/estimator.md).
        const float u3 = sampler ? rng.nextFloat() : 0.0f;
        const ScatterDraw s = sampleScatter(mat, frame, sampler, wo, u1, u2, u3);
        if (!s.valid || !(s.pdf > 0.0f) || s.wi.z <= 0.0f) {
            if (vertex) vertex->end = "no valid direction";
            break;
        }
        const glm::vec3 wi = frame.toWorld(s.wi);
        if (glm::dot(wi, ng) <= 0.0f) { // below the true surface: light leak otherwise
            if (vertex) vertex->end = "below the geometric surface";
            break;
        }
        if (vertex) {
            vertex->technique = s.technique;
            vertex->pdf = s.pdf;
            if (sampler)
                for (const ComponentPdf& c : sampler->componentPdfs(wi)) {
                    vertex->pdfs.push_back({std::string(c.technique), c.pdf});
                    vertex->pdfs.push_back({"share:" + std::string(c.technique), c.weight});
                }
            else
                vertex->pdfs.push_back({"bsdf", s.pdf});
            vertex->fcos = s.f * s.wi.z;
            techniqueOfDir = s.technique;
            fcosOfDir = s.f * s.wi.z;
            betaBeforeDir = beta;
        }
        beta *= s.f * (s.wi.z / s.pdf);
        scatterPdfOfDir = s.pdf;

        if (depth >= kRussianRouletteDepth) {
            float q = std::max(kMinContinueProbability,
                               1.0f - std::max(beta.r, std::max(beta.g, beta.b)));
            if (vertex) vertex->continueProbability = 1.0f - q;
            if (rng.nextFloat() < q) {
                if (vertex) vertex->end = "russian roulette";
                break;
            }
            beta /= 1.0f - q;
        }
        if (vertex) vertex->throughputOut = beta;
        if (neeSampler)
            neeOfDir = std::move(ds);
        else
            neeOfDir.reset();

        origin = next;
        dir = wi;
    }
    if (record) record->value = L;
    return L;
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
                                      const DirectionSampler& nee, const glm::vec3& wo,
                                      const glm::vec3& ng, const glm::vec3& origin, float u1,
                                      float u2, float u3, std::vector<PathEvent>* events,
                                      int vertex, const glm::vec3& beta) const {
    const DirectionSample d = nee.sample(u1, u2, u3);
    if (!d.valid) return glm::vec3(0.0f);
    // The continuation ends paths below the true surface or the shading hemisphere: NEE agrees.
    if (glm::dot(d.wi, ng) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 wi = frame.toLocal(d.wi);
    if (wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 f = mat.brdf->eval(mat.params, wo, wi);
    if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
    if (scene::occluded(*m_bvh, origin, d.wi, 0.0f, std::numeric_limits<float>::max()))
        return glm::vec3(0.0f);
    const glm::vec3 Le = m_environment.radiance(d.wi);
    // `env`: light sampling alone; the others: power heuristic against the BSDF continuation.
    const float bsdfPdf =
        m_options.sampler == SamplerKind::Env ? 0.0f : mat.brdf->pdf(mat.params, wo, wi);
    const float w = m_options.sampler == SamplerKind::Env ? 1.0f : powerWeight(d.pdf, bsdfPdf);
    const glm::vec3 value = f * Le * (wi.z * w / d.pdf);
    if (events && value != glm::vec3(0.0f)) {
        PathEvent e;
        e.vertex = vertex;
        e.kind = "env-nee";
        e.technique = d.technique;
        e.pdf = d.pdf;
        for (const ComponentPdf& c : nee.componentPdfs(d.wi)) {
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
    const int pass = m_passes;
    std::atomic<int> next{0};
    // Workers write disjoint pixels of m_sum: no locking.
    auto worker = [&] {
        for (int tile = next++; tile < tiles; tile = next++) {
            int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
            for (int y = y0; y < std::min(y0 + kTileSize, h); ++y)
                for (int x = x0; x < std::min(x0 + kTileSize, w); ++x)
                    m_sum[size_t(y) * size_t(w) + size_t(x)] += glm::dvec3(samplePixel(x, y, pass));
        }
    };
    const int n = std::min(m_threadCount, tiles);
    std::vector<std::thread> threads;
    threads.reserve(size_t(std::max(0, n - 1)));
    for (int i = 1; i < n; ++i) threads.emplace_back(worker);
    worker(); // the calling thread is worker 0
    for (std::thread& t : threads) t.join();
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

void CpuPathTracer::resetAccumulation() {
    std::fill(m_sum.begin(), m_sum.end(), glm::dvec3(0.0));
    m_passes = 0;
    m_timings.passSeconds = 0.0;
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
