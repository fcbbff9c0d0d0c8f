// CpuPathTracer::samplePixel: one path of docs/estimator.md, term for term (the rest of the
// tracer, scene swaps and passes, is cpu_path_tracer.cpp).
#include "render/reference/cpu_path_tracer.h"

#include "render/reference/cpu_surface.h"
#include "util/hemisphere_sampling.h"
#include "util/path_sampler.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

namespace wavelit::render {
namespace {

// docs/estimator.md constants, shared with shaders/path_tracer.comp.
constexpr float kRayOffset = 1e-4f;                      // × max(1, |hit|): scale-aware epsilon
constexpr float kMinContinueProbability = 0.05f;         // Russian roulette floor of q's complement
constexpr int kRussianRouletteDepth = 2;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

} // namespace

glm::vec3 CpuPathTracer::samplePixel(int x, int y, int pass, PathRecord* record,
                                     glm::vec3* groups) const {
    const uint64_t pixelIndex = uint64_t(y) * uint64_t(m_options.width) + uint64_t(x);
    util::PathSampler rng(util::PathSampler::seedKey(m_options.seed), uint32_t(pixelIndex),
                          uint32_t(pass));
    // Draws are separate statements: C++ leaves the order of function arguments unspecified,
    // and the draw order is part of the estimator.
    const auto [jx, jy] = rng.next2D();

    glm::vec3 origin = m_camera.origin();
    glm::vec3 dir = m_camera.direction(x, y, jx, jy);
    glm::vec3 L(0.0f), beta(1.0f);
    float scatterPdfOfDir = 0.0f; // solid-angle pdf with which the last vertex drew `dir`
    const SamplerKind kind = m_options.sampler;
    const bool envNee = samplerHasEnvNee(kind);
    const bool lit = m_samplerTables && m_samplerTables->environment().hasLight();
    // The env NEE technique of the vertex that drew `dir` (issue 20), kept so that env light the
    // continuation finds is MIS-weighted against it; empty: that vertex did no env NEE.
    // (A pointer: the camera vertex's may be the pixel's cached entry; a sampler built for the
    // path lives in neeStorage.)
    std::optional<DirectionSampler> neeStorage;
    const DirectionSampler* neeOfDir = nullptr;
    bool envOnlyNeeOfDir = false; // that vertex's NEE was the env technique alone (no sampler)
    // LightMix: each term below is also added to its emitter's group (docs/estimator.md "Light
    // groups"), the same float value that is added to L.
    if (groups) std::fill(groups, groups + m_groups.size(), glm::vec3(0.0f));
    auto splat = [&](int group, const glm::vec3& term) {
        if (groups && group >= 0) groups[group] += term;
    };
    std::vector<glm::vec3> perLight(groups ? m_lights.size() : 0);
    if (record) {
        *record = PathRecord{};
        record->x = x;
        record->y = y;
        record->pass = pass;
    }
    // Path record helpers (no-ops without a record; no string is built per path without one).
    const char* techniqueOfDir = "camera";
    glm::vec3 fcosOfDir(1.0f), betaBeforeDir(1.0f);
    auto addEvent = [&](int vertex, const char* eventKind, std::string_view technique,
                        double pdf, std::vector<PathPdf> pdfs, double weight, glm::vec3 fcos,
                        glm::vec3 radiance, glm::vec3 throughput, glm::vec3 contribution) {
        if (!record || contribution == glm::vec3(0.0f)) return;
        record->events.push_back(PathEvent{vertex, eventKind, std::string(technique), pdf,
                                           std::move(pdfs), weight, fcos, radiance, throughput,
                                           contribution});
    };
    for (int depth = 0;; ++depth) {
        const int from = depth - 1; // the vertex that drew `dir`
        scene::BvhHit hit;
        const bool found =
            scene::intersect(*m_bvh, origin, dir, 0.0f, std::numeric_limits<float>::max(), hit);
        // Analytic lights crossed before the surface (or the sun, when the ray escapes).
        if (!m_lights.empty()) {
            const glm::vec3 e = m_lights.emissionAlongRay(
                origin, dir, found ? hit.t : kInfinity, scatterPdfOfDir, depth == 0,
                m_lightStrategy, groups ? perLight.data() : nullptr);
            L += beta * e;
            for (size_t k = 0; k < perLight.size(); ++k)
                splat(m_groups.groupOfLight[k], beta * perLight[k]);
            addEvent(from, "light-hit", techniqueOfDir, scatterPdfOfDir, {}, 1.0, fcosOfDir, e,
                     betaBeforeDir, beta * e);
        }
        if (!found) {
            // Direct env light was estimated at the previous vertex by NEE: weight the
            // continuation's find against it (`env`: NEE alone, so 0).
            // One equirect point for the radiance and the NEE's env pdf (the same texel).
            const glm::vec2 envUv = m_environment.equirect(dir);
            float w = 1.0f, neePdf = 0.0f;
            if (neeOfDir || envOnlyNeeOfDir) {
                neePdf = neeOfDir ? neeOfDir->pdf(dir, envUv)
                                  : float(m_samplerTables->environment().pdfUv(envUv));
                w = kind == SamplerKind::Env ? 0.0f : powerWeight(scatterPdfOfDir, neePdf);
            }
            const glm::vec3 e = m_environment.radianceAt(envUv);
            L += beta * (w * e);
            splat(m_groups.environmentGroup, beta * (w * e));
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
        if (mat.emission != glm::vec3(0.0f)) splat(m_groups.emissionGroup, beta * mat.emission);
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
        // sample. `bsdf`: none. The env technique alone (`mis`, `env`, `wavelet` past its
        // product vertices) needs no sampler object: sampleEnvTechnique draws what one would, bit
        // for bit (envOnlyNee).
        std::optional<DirectionSampler> own;
        const DirectionSampler* ds = nullptr;
        bool envOnlyNee = false;
        if (m_samplerTables && mat.samplerIndex >= 0 &&
            (continuationFromSampler(kind) || (envNee && lit))) {
            const ShadingPoint here{frame.n, frame.t, frame.b, -dir, size_t(mat.samplerIndex)};
            if (!continuationFromSampler(kind) &&
                vertexSamplerKind(kind, depth) == SamplerKind::Env) {
                envOnlyNee = true;
            } else if (kind == SamplerKind::Wavelet && depth == 0) {
                ds = cameraNeeSampler(own, x, y, mat, here);
            } else {
                own.emplace(*m_samplerTables, vertexSamplerKind(kind, depth), here);
                ds = &*own;
            }
        }
        const DirectionSampler* sampler = ds && continuationFromSampler(kind) ? ds : nullptr;
        const DirectionSampler* neeSampler = ds && envNee ? ds : nullptr;

        // Lights are sampled from the point the continuation ray leaves from, so both MIS
        // strategies evaluate their pdfs at the same point.
        const glm::vec3 next =
            sp.position + ng * (kRayOffset * std::max(1.0f, glm::length(sp.position)));
        if (!m_lights.empty()) {
            const float uSelect = rng.next1D();
            const auto [ul1, ul2] = rng.next2D();
            PathEvent lightEvent;
            const glm::vec3 e = nextEvent(mat, frame, sampler, wo, ng, next, uSelect, ul1, ul2,
                                          vertex ? &lightEvent : nullptr);
            L += beta * e;
            if (groups) splat(m_groups.groupOfLight[m_lights.select(uSelect)], beta * e);
            addEvent(depth, "light-nee", lightEvent.technique, lightEvent.pdf,
                     std::move(lightEvent.misPdfs), lightEvent.weight, lightEvent.fcos,
                     lightEvent.radiance, beta, beta * e);
        }

        if (envNee) {
            // Drawn for every scattering vertex of these kinds, used where the vertex has an env
            // NEE technique (docs/estimator.md "Random numbers").
            const auto [ue1, ue2] = rng.next2D();
            const float ue3 = rng.next1D();
            if (neeSampler || envOnlyNee) {
                const glm::vec3 e =
                    envNextEvent(mat, frame, neeSampler, wo, ng, next, ue1, ue2, ue3,
                                 vertex ? &record->events : nullptr, depth, beta);
                L += beta * e;
                splat(m_groups.environmentGroup, beta * e);
            }
        }

        const auto [u1, u2] = rng.next2D();
        // The technique choice of a DirectionSampler mixture: drawn only when one draws the
        // continuation (uniform, cosine), the draw order the Vulkan tracer shares
        // (docs/estimator.md).
        const float u3 = sampler ? rng.next1D() : 0.0f;
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
            if (rng.next1D() < q) {
                if (vertex) vertex->end = "russian roulette";
                break;
            }
            beta /= 1.0f - q;
        }
        if (vertex) vertex->throughputOut = beta;
        if (neeSampler && own && ds == &*own) {
            neeStorage = std::move(own);
            neeOfDir = &*neeStorage;
        } else {
            neeOfDir = neeSampler; // a cached entry, or none
        }
        envOnlyNeeOfDir = envOnlyNee;

        origin = next;
        dir = wi;
    }
    if (record) record->value = L;
    return L;
}

} // namespace wavelit::render
