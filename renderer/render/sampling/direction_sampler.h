// Direction samplers for environment lighting at a shading point (issue 6; architecture.md §4, §5.B):
// one interface for every `--sampler` kind, so both tracers draw, weight and report the same way.
//
//   uniform  uniform hemisphere around the shading normal        pdf 1/(2 pi)
//   cosine   cosine-weighted hemisphere                           pdf cos/pi
//   bsdf     the material's BRDF sampler (GGX: visible normals)   the plugin's pdf
//   env      the environment alone, hierarchical over its octahedral map (rotation applied)
//   mis      one-sample MIS of bsdf and env, 1/2 each: pdf = (p_bsdf + p_env) / 2, which is the
//            balance heuristic in the one-sample model (f L cos / sum c_i p_i). The path tracers
//            do not use this mixture: their `mis` is env NEE + BSDF continuation, MIS-weighted
//            (samplerHasEnvNee below; docs/estimator.md "Direction samplers")
//   wavelet  the product sampler (env localised around the reflection vector x BRDF x cos,
//            refined below its leaves by BRDF-weighted env levels, then the env pyramid,
//            env_product_sampler.h) for the lobe, plus bsdf (the policy's share, 0.1,
//            defensive) and env sampling with a per-point share c_env ~ sqrt(M_tail) /
//            (sqrt(M_tail) + sqrt(M_lobe)) (second moments estimated on 8^2 coarse cells /
//            4x4 BSDF strata), clamped to [0.05, 0.8] (values: sampler_constants.h, shared
//            with the Vulkan tracer): pdf = sum c_i p_i, so no direction with a
//            non-zero integrand has zero pdf. Lobes narrower than 2 env texels (policy BsdfLobe)
//            use bsdf for the lobe + env with the same share rule; black env / all-zero
//            product: bsdf alone.
//   oracle   a dense 128^2 product of BRDF x cos and the env over a lobe-fitted window at the
//            exact reflection vector, refined by the env pyramid (oracle_sampler.h): the ideal
//            the wavelet sampler approximates; 0.05 bsdf, env share as for wavelet but >= 0.02.
//
// Contract for the tracers: build DirectionSamplerTables (direction_sampler_tables.h) once per
// scene (and again after change sets touching the environment or a material; rebuilding is per
// material, see build()), then per
// shading point construct a DirectionSampler (the wavelet kind does its per-point product work
// here: ~1k BRDF evaluations + a 32^2 sparse product) and call sample(u1, u2, u3): u3 picks the
// technique, u1, u2 drive it. The returned pdf is the mixture's pdf in SOLID ANGLE at the
// direction drawn: pdf(wi) for BSDF-type draws; for env/product draws the tabulated parts are
// evaluated at the double-precision direction before rounding to float (pdf(wi) agrees except
// for the ~1e-7 of draws that rounding moves across a texel edge, where the double value is the
// right one: a sun texel is 1e6 x denser than its neighbours); the estimator is f(wo, wi) L(wi) cos / pdf
// (never the paper's eq 7). `valid` is false when no direction was produced (e.g. GGX reflected
// below the horizon); a valid wi may still lie below the surface, where f = 0.
// All directions are WORLD space unit vectors. Thread-safety: const methods are thread-safe;
// one DirectionSampler per shading point per thread.
#pragma once

#include "plugins/brdf.h"
#include "render/sampling/direction_sampler_tables.h"
#include "render/sampling/product/env_product_sampler.h"
#include "render/session/render_options.h"

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wavelit::render {

// SamplerKind, samplerKindName and parseSamplerKind live in render_options.h (the CLI's flag).
std::vector<SamplerKind> allSamplerKinds();

// What each kind means in the path tracers (issue 20; docs/estimator.md "Direction samplers"):
// `uniform`, `cosine` and `bsdf` draw the path's continuation and nothing else; `env`, `mis`,
// `wavelet` and `oracle` estimate DIRECT environment light by next-event estimation (a direction
// from this kind's vertex sampler, a shadow ray) and continue the path by BSDF sampling; `mis`
// MIS-weights the two (power heuristic), `env` counts env light found by the continuation as 0
// (light sampling alone), `wavelet` and `oracle` MIS-weight their product mixture against the BSDF.
bool samplerHasEnvNee(SamplerKind kind);
// The continuation is drawn by a DirectionSampler (uniform, cosine), not by the plugin.
bool continuationFromSampler(SamplerKind kind);
// The kind the DirectionSampler of a path's scattering vertex `depth` (0: the camera ray's hit) is
// built with: `mis`'s NEE draws from `env` alone, and so does `wavelet`'s from vertex
// kWaveletProductVertices on (sampler_constants.h).
SamplerKind vertexSamplerKind(SamplerKind kind, int depth);

// The shading configuration: an orthonormal frame (n = shading normal, t, b tangents; the BRDF's
// local frame is (t, b, n)), the direction toward the viewer, and the material's index in the
// tables.
struct ShadingPoint {
    glm::vec3 n{0.0f, 1.0f, 0.0f}, t{1.0f, 0.0f, 0.0f}, b{0.0f, 0.0f, -1.0f};
    glm::vec3 wo{0.0f, 1.0f, 0.0f};
    size_t material = 0;
};

struct DirectionSample {
    glm::vec3 wi{0.0f};
    float pdf = 0.0f; // solid angle
    bool valid = false;
    const char* technique = ""; // the mixture component that drew wi (for path records)
    // Where the mixture has the env technique: the equirect point of wi whose texel its pdf read
    // (SamplerEnvironment::equirect), so that the tracer reads the radiance there without a
    // second atan2 and acos (CpuEnvironment::radianceAt). Negative: not computed.
    glm::vec2 envUv{-1.0f};
};

// One mixture component's share and pdf at a direction (path records, issue 20).
struct ComponentPdf {
    const char* technique;
    double weight;
    double pdf; // solid angle, of the component alone
};

// The `env` technique alone, drawn exactly (bit for bit: wi, pdf, envUv, valid) as a
// DirectionSampler of kind Env over a lit environment draws it with (u1, u2), without building
// one: what the tracers' env-only NEE vertices (`mis`, `env`, `wavelet` past its product
// vertices) draw on every path. Its pdf at a direction is env.pdfUv(env.equirect(wi)).
DirectionSample sampleEnvTechnique(const SamplerEnvironment& env, float u1, float u2);

// How the `wavelet` kind forms its per-point product. Paper: the sparse product of the truncated
// env factor and the truncated BRDF x cos at the policy's 2^5 leaves (wavelet/product.h), the
// method's reference. Tracer: what both path tracers use at their product vertices (the Vulkan
// kernel's build, sampler_constants.h kTracerMaxProductLevel): the env factor synthesised to at
// most 2^4 leaves times the env-weighted BRDF x cos, dense and untruncated, with the narrow-lobe
// BSDF share; 4x fewer BRDF evaluations and nodes, and the same mixture on both devices.
enum class ProductBuild { Paper, Tracer };

class DirectionSampler {
public:
    // `tables` must outlive the sampler. `kind` may differ from tables.kind() except that
    // Wavelet needs tables built for Wavelet (others fall back to bsdf + env mixing).
    DirectionSampler(const DirectionSamplerTables& tables, SamplerKind kind,
                     const ShadingPoint& point, ProductBuild build = ProductBuild::Paper);

    DirectionSample sample(float u1, float u2, float u3) const;
    float pdf(const glm::vec3& wi) const;
    // The same, given wi's equirect point envUv (SamplerEnvironment::equirect(wi)), which the
    // caller also reads the radiance at.
    float pdf(const glm::vec3& wi, const glm::vec2& envUv) const;
    double pdfDouble(const glm::vec3& wi) const;
    // Every component's share and own pdf at world direction wi (sum of weight x pdf = pdf(wi)).
    std::vector<ComponentPdf> componentPdfs(const glm::vec3& wi) const;
    // What this sampler does at this point and why (for the render report).
    std::string describe() const;
    // The env technique alone (`env`, `mis`'s NEE, `wavelet` past its product vertices or under
    // the EnvMis policy): the tracers play `mis`'s shadow-ray roulette on such NEE draws.
    bool envTechniqueOnly() const {
        return m_components.size() == 1 && m_components[0].technique == Technique::Env;
    }

    // f(wo, wi) cos(theta_i) as RGB, the BRDF part of the integrand (0 below the surface).
    glm::vec3 brdfCos(const glm::vec3& wi) const;

private:
    enum class Technique { Uniform, Cosine, Bsdf, Env, Product };
    struct Component {
        Technique technique;
        double weight;
    };
    glm::vec3 toShading(const glm::vec3& w) const;
    glm::vec3 fromShading(const glm::vec3& w) const;
    // envUv: wi's equirect point if known (x >= 0), else set here when the env technique needs it.
    double techniquePdf(Technique t, const glm::vec3& wi, const glm::vec3& local,
                        const glm::dvec3& envLocal, glm::vec2& envUv) const;
    // productPdf >= 0: the product technique's pdf at envLocal, already known (its draw walked
    // the descent a pdf walk would repeat, the lobe refinement's BRDF evaluations included);
    // < 0: walk it.
    double mixturePdf(const glm::vec3& wi, const glm::dvec3& envLocal, double productPdf,
                      glm::vec2& envUv) const;
    void addProduct(SamplerKind kind);
    // Luminance of brdfCos at each ENV-LOCAL direction (out sized alike), the BRDF as a batch.
    void brdfCosLuminance(const std::vector<glm::dvec3>& envLocal, std::vector<double>& out) const;
    double productLobeMoment() const;
    double bsdfLobeMoment() const;
    double tailEnvMoment(const glm::dvec3& axisLocal, double capAngle) const;

    const DirectionSamplerTables* m_tables;
    SamplerKind m_kind;
    ProductBuild m_build;
    ShadingPoint m_point;
    const SamplerMaterial* m_material;
    glm::vec3 m_woLocal;
    std::vector<Component> m_components;
    std::optional<EnvProductSampler> m_product;
    std::string m_describe;
    const std::string* m_envMisReason = nullptr; // the tables' policy reason (EnvMis)
};

} // namespace wavelit::render
