#include "render/sampling/direction_sampler.h"

#include "render/sampling/oracle_sampler.h"
#include "render/sampling/sampler_constants.h"
#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wavelit::render {
// samplerKindName lives in render_options.cpp (one name table for CLI and samplers).

std::vector<SamplerKind> allSamplerKinds() {
    return {SamplerKind::Uniform, SamplerKind::Cosine, SamplerKind::Bsdf, SamplerKind::Env,
            SamplerKind::Mis,     SamplerKind::Wavelet, SamplerKind::Oracle};
}

bool samplerHasEnvNee(SamplerKind kind) {
    return kind == SamplerKind::Env || kind == SamplerKind::Mis || kind == SamplerKind::Wavelet ||
           kind == SamplerKind::Oracle;
}

bool continuationFromSampler(SamplerKind kind) {
    return kind == SamplerKind::Uniform || kind == SamplerKind::Cosine;
}

SamplerKind vertexSamplerKind(SamplerKind kind, int depth) {
    if (kind == SamplerKind::Mis)
        return SamplerKind::Env;
    if (kind == SamplerKind::Wavelet && depth >= kWaveletProductVertices)
        return SamplerKind::Env;
    return kind;
}

DirectionSample sampleEnvTechnique(const SamplerEnvironment& env, float u1, float u2) {
    // DirectionSampler::sample's env branch with the one component of weight 1: the mixture pdf
    // 0 + 1 x p is p exactly.
    DirectionSample out;
    out.technique = "env";
    const glm::dvec3 local = env.sampleLocal(glm::dvec2(u1, u2)).direction;
    out.wi = glm::vec3(glm::normalize(env.toWorld(local)));
    out.envUv = env.equirect(out.wi);
    out.pdf = float(env.pdfUv(out.envUv));
    out.valid = std::isfinite(out.wi.x) && out.pdf > 0.0f && std::isfinite(out.pdf);
    return out;
}

DirectionSampler::DirectionSampler(const DirectionSamplerTables& tables, SamplerKind kind,
                                   const ShadingPoint& point, ProductBuild build)
    : m_tables(&tables), m_kind(kind), m_build(build), m_point(point),
      m_material(&tables.material(point.material)) {
    m_woLocal = toShading(point.wo);
    const bool lit = tables.environment().hasLight();
    switch (kind) {
    case SamplerKind::Uniform:
        m_components = {{Technique::Uniform, 1.0}};
        break;
    case SamplerKind::Cosine:
        m_components = {{Technique::Cosine, 1.0}};
        break;
    case SamplerKind::Bsdf:
        m_components = {{Technique::Bsdf, 1.0}};
        break;
    case SamplerKind::Env:
        m_components = {{lit ? Technique::Env : Technique::Bsdf, 1.0}};
        break;
    case SamplerKind::Mis:
        if (lit)
            m_components = {{Technique::Bsdf, kMisWeight}, {Technique::Env, 1.0 - kMisWeight}};
        else
            m_components = {{Technique::Bsdf, 1.0}};
        break;
    case SamplerKind::Wavelet:
    case SamplerKind::Oracle:
        addProduct(kind);
        break;
    }
}

void DirectionSampler::addProduct(SamplerKind kind) {
    const SamplerEnvironment& env = m_tables->environment();
    const bool aroundNormal = m_material->brdf->lobeAxis() == plugins::BrdfLobeAxis::Normal;
    const glm::vec3 n = m_point.n, wo = m_point.wo;
    const glm::vec3 axisWorld = aroundNormal ? n : 2.0f * glm::dot(wo, n) * n - wo;
    const glm::dvec3 axis = env.toLocal(glm::normalize(glm::dvec3(axisWorld)));
    auto brdfCosLocal = [&](const glm::dvec3& dLocal) {
        return double(util::luminance(brdfCos(glm::vec3(env.toWorld(dLocal)))));
    };
    m_components = {{Technique::Bsdf, 1.0}};
    if (!env.hasLight()) {
        m_describe = std::string(samplerKindName(kind)) + ": black environment, bsdf";
        return;
    }
    double bsdfShare = kOracleBsdfShare;
    double capAngle = oracleCapHalfAngle(*m_material->brdf, m_material->params);
    if (kind == SamplerKind::Oracle) {
        m_product = buildOracleProduct(env, axis, capAngle, brdfCosLocal);
        m_describe = m_product ? "oracle: dense 128^2 product, refined" : "oracle: all-zero "
                                                                         "product, bsdf lobe";
    } else {
        const MaterialProductTables* tables = m_tables->productTables(m_point.material);
        if (!tables) {
            m_describe = "wavelet: no product tables built (tables are not for `wavelet`), bsdf";
            return;
        }
        const ProductPolicy& policy = tables->policy();
        if (policy.mode == ProductMode::EnvMis) {
            // `mis`'s NEE technique: the env alone (the tracer MIS-weights it against the BSDF
            // continuation, as at a `wavelet` path's deeper vertices).
            m_components = {{Technique::Env, 1.0}};
            m_envMisReason = &policy.reason; // described on demand (describe())
            return;
        }
        bsdfShare = policy.mixBsdf;
        capAngle = policy.capHalfAngle;
        if (policy.mode == ProductMode::BsdfLobe) {
            m_describe = "wavelet, bsdf lobe: " + policy.reason;
        } else {
            const int bin = tables->binOf(axis);
            const ProductWindow window = tables->window(bin);
            const bool tracer = m_build == ProductBuild::Tracer;
            const int level = tracer ? tracerProductLevel(policy) : policy.productLevel;
            // BRDF x cos averaged over 2x2 points per texel, weighted by the env's sub-cells, so
            // the product's leaf masses are those of the product at 2x its resolution; the
            // tracers' from the texels' corners (the kernel's twin).
            auto brdfCos = [&](const std::vector<glm::dvec3>& d, std::vector<double>& out) {
                brdfCosLuminance(d, out);
            };
            const wavelet::SquareGrid brdfGrid =
                tracer ? windowTabulateEnvWeightedCornersBatch(env, window, level, brdfCos)
                       : windowTabulateEnvWeightedBatch(env, window, level, brdfCos, 2);
            m_product =
                tracer ? EnvProductSampler::buildDense(
                             env, window, tracerProductLeaves(tables->envFactor(bin), brdfGrid))
                       : EnvProductSampler::buildSparse(env, window, tables->envFactor(bin),
                                                        brdfGrid, policy.brdfKeep);
            if (tracer && !policy.aroundNormal && policy.capHalfAngle < kTracerNarrowLobeCap)
                bsdfShare = std::max(bsdfShare, kTracerNarrowLobeMixBsdf);
            if (m_product) {
                // The refinement's BRDF x cos, captured by value (the sampler may be moved).
                const plugins::Brdf* brdf = m_material->brdf;
                const plugins::BrdfParams params = m_material->params;
                const glm::vec3 woLocal = m_woLocal;
                const glm::dvec3 t = env.toLocal(glm::dvec3(m_point.t));
                const glm::dvec3 bt = env.toLocal(glm::dvec3(m_point.b));
                const glm::dvec3 nl = env.toLocal(glm::dvec3(m_point.n));
                m_product->setLobeRefinement(
                    [=](const glm::dvec3 (&d)[4], double (&out)[4]) {
                        // The directions above the shading horizon as one BRDF batch (its floats
                        // are eval's); the others weigh 0.
                        float x[4], y[4], z[4], r[4], g[4], b[4];
                        int slot[4], n = 0;
                        for (int c = 0; c < 4; ++c) {
                            out[c] = 0.0;
                            const float lz = float(glm::dot(d[c], nl));
                            if (lz <= 0.0f)
                                continue;
                            x[n] = float(glm::dot(d[c], t));
                            y[n] = float(glm::dot(d[c], bt));
                            z[n] = lz;
                            slot[n++] = c;
                        }
                        brdf->evalBatch(params, woLocal, {x, y, z, size_t(n)}, {r, g, b});
                        for (int k = 0; k < n; ++k)
                            out[slot[k]] =
                                double(util::luminance(glm::vec3(r[k], g[k], b[k]) * z[k]));
                    },
                    lobeRefineLevels(policy, window, level, env.level()));
            }
            m_describe = m_product ? "wavelet product: " + policy.reason
                                   : "wavelet: all-zero product here, bsdf lobe";
        }
    }
    // Shares of the one-sample mixture. If each technique served only its own part of the
    // integrand, Var + I^2 = sum_i M_i / c_i (M_i: that part's second moment under technique i
    // alone), least for c_i ~ sqrt(M_i). The lobe part is the lobe technique's (product, else
    // bsdf); the rest (a sun in the BRDF's tail) is env sampling's, estimated on coarse cells.
    const double lobeMoment = m_product ? productLobeMoment() : bsdfLobeMoment();
    const double tailMoment = tailEnvMoment(axis, capAngle);
    const double a = std::sqrt(std::max(tailMoment, 0.0)), b = std::sqrt(std::max(lobeMoment, 0.0));
    const double minEnvShare =
        kind == SamplerKind::Oracle ? kOracleMinEnvShare : kWaveletMinEnvShare;
    const double envShare = std::clamp(a / std::max(a + b, 1e-300), minEnvShare, kMaxEnvShare);
    if (m_product)
        m_components = {{Technique::Product, 1.0 - envShare - bsdfShare},
                        {Technique::Bsdf, bsdfShare},
                        {Technique::Env, envShare}};
    else
        m_components = {{Technique::Bsdf, 1.0 - envShare}, {Technique::Env, envShare}};
    char buf[96];
    std::snprintf(buf, sizeof buf, " [env share %.2f]", envShare);
    m_describe += buf;
}

glm::vec3 DirectionSampler::toShading(const glm::vec3& w) const {
    return {glm::dot(w, m_point.t), glm::dot(w, m_point.b), glm::dot(w, m_point.n)};
}

glm::vec3 DirectionSampler::fromShading(const glm::vec3& w) const {
    return w.x * m_point.t + w.y * m_point.b + w.z * m_point.n;
}

void DirectionSampler::brdfCosLuminance(const std::vector<glm::dvec3>& envLocal,
                                        std::vector<double>& out) const {
    // brdfCos's arithmetic, the BRDF evaluated as one batch (a GGX batch computes Lambda(wo) once
    // and vectorises; its floats are eval's).
    const SamplerEnvironment& env = m_tables->environment();
    std::vector<float> x, y, z, r, g, b;
    std::vector<size_t> above; // indices of the directions above the shading horizon
    for (size_t i = 0; i < envLocal.size(); ++i) {
        const glm::vec3 l = toShading(glm::vec3(env.toWorld(envLocal[i])));
        out[i] = 0.0;
        if (l.z <= 0.0f)
            continue;
        above.push_back(i);
        x.push_back(l.x);
        y.push_back(l.y);
        z.push_back(l.z);
    }
    r.resize(above.size());
    g.resize(above.size());
    b.resize(above.size());
    m_material->brdf->evalBatch(m_material->params, m_woLocal,
                                {x.data(), y.data(), z.data(), above.size()},
                                {r.data(), g.data(), b.data()});
    for (size_t k = 0; k < above.size(); ++k)
        out[above[k]] = double(util::luminance(glm::vec3(r[k], g[k], b[k]) * z[k]));
}

glm::vec3 DirectionSampler::brdfCos(const glm::vec3& wi) const {
    const glm::vec3 l = toShading(wi);
    if (l.z <= 0.0f)
        return glm::vec3(0.0f);
    return m_material->brdf->eval(m_material->params, m_woLocal, l) * l.z;
}

double DirectionSampler::techniquePdf(Technique t, const glm::vec3& wi, const glm::vec3& local,
                                      const glm::dvec3& envLocal, glm::vec2& envUv) const {
    switch (t) {
    case Technique::Uniform:
        return util::uniformHemispherePdf(local);
    case Technique::Cosine:
        return util::cosineHemispherePdf(local);
    case Technique::Bsdf:
        return m_material->brdf->pdf(m_material->params, m_woLocal, local);
    case Technique::Env: // the texel the radiance reads at wi
        if (!(envUv.x >= 0.0f))
            envUv = m_tables->environment().equirect(wi);
        return m_tables->environment().pdfUv(envUv);
    case Technique::Product:
        return m_product->pdfLocal(envLocal);
    }
    return 0.0;
}

double DirectionSampler::mixturePdf(const glm::vec3& wi, const glm::dvec3& envLocal,
                                    double productPdf, glm::vec2& envUv) const {
    const glm::vec3 local = toShading(wi);
    double p = 0.0;
    for (const Component& c : m_components)
        p += c.weight * (c.technique == Technique::Product && productPdf >= 0.0
                             ? productPdf
                             : techniquePdf(c.technique, wi, local, envLocal, envUv));
    return p;
}

double DirectionSampler::pdfDouble(const glm::vec3& wi) const {
    glm::vec2 envUv(-1.0f);
    return mixturePdf(wi, m_tables->environment().toLocal(glm::dvec3(wi)), -1.0, envUv);
}

float DirectionSampler::pdf(const glm::vec3& wi) const { return float(pdfDouble(wi)); }

float DirectionSampler::pdf(const glm::vec3& wi, const glm::vec2& envUv) const {
    glm::vec2 uv = envUv;
    return float(mixturePdf(wi, m_tables->environment().toLocal(glm::dvec3(wi)), -1.0, uv));
}

namespace {
const char* techniqueName(int t) {
    static const char* const names[] = {"uniform", "cosine", "bsdf", "env", "product"};
    return names[t];
}
} // namespace

std::vector<ComponentPdf> DirectionSampler::componentPdfs(const glm::vec3& wi) const {
    const glm::vec3 local = toShading(wi);
    const glm::dvec3 envLocal = m_tables->environment().toLocal(glm::dvec3(wi));
    std::vector<ComponentPdf> out;
    glm::vec2 envUv(-1.0f);
    for (const Component& c : m_components)
        out.push_back({techniqueName(int(c.technique)), c.weight,
                       techniquePdf(c.technique, wi, local, envLocal, envUv)});
    return out;
}

DirectionSample DirectionSampler::sample(float u1, float u2, float u3) const {
    // u3 picks the technique (cumulative weights); the last one absorbs rounding.
    size_t pick = 0;
    double start = 0.0;
    for (; pick + 1 < m_components.size(); ++pick) {
        if (double(u3) < start + m_components[pick].weight)
            break;
        start += m_components[pick].weight;
    }
    const glm::dvec2 u(u1, u2);
    const SamplerEnvironment& env = m_tables->environment();
    glm::vec3 wi(0.0f);
    std::optional<glm::dvec3> envLocal;
    double productPdf = -1.0; // known when the product drew
    switch (m_components[pick].technique) {
    case Technique::Uniform:
        wi = fromShading(util::sampleUniformHemisphere({u1, u2}));
        break;
    case Technique::Cosine:
        wi = fromShading(util::sampleCosineHemisphere({u1, u2}));
        break;
    case Technique::Bsdf: {
        const plugins::BrdfSample s =
            m_material->brdf->sample(m_material->params, m_woLocal, u1, u2);
        if (!s.valid)
            return {};
        wi = fromShading(s.wi);
        break;
    }
    case Technique::Env:
        envLocal = env.sampleLocal(u).direction;
        break;
    case Technique::Product: {
        const wavelet::DirectionSample s = m_product->sampleLocal(u);
        envLocal = s.direction;
        productPdf = s.pdf;
        break;
    }
    }
    DirectionSample out;
    out.technique = techniqueName(int(m_components[pick].technique));
    if (envLocal) {
        // Tabulated techniques: the product's pdf is evaluated at the double direction that was
        // drawn (when the product drew it, its descent's own pdf, as the kernel does). Rounding
        // it to float can cross into a neighbouring texel (1e-7 of the time); a sun's texel next
        // to sky is 1e6 x denser, so pdf(float wi) there would be a firefly.
        // The env technique's pdf is read at the float wi (pdfWorld), the texel whose radiance
        // the tracer then reads, so L / p_env stays the env integral either way.
        out.wi = glm::vec3(glm::normalize(env.toWorld(*envLocal)));
        out.pdf = float(mixturePdf(out.wi, *envLocal, productPdf, out.envUv));
    } else {
        out.wi = glm::normalize(wi);
        out.pdf = float(mixturePdf(out.wi, env.toLocal(glm::dvec3(out.wi)), -1.0, out.envUv));
    }
    out.valid = std::isfinite(out.wi.x) && out.pdf > 0.0f && std::isfinite(out.pdf);
    return out;
}

std::string DirectionSampler::describe() const {
    // The plain kinds name themselves here, not in the constructor: the tracers build one sampler
    // per vertex and almost never ask (a string per vertex was ~3% of a `mis` pass).
    if (m_envMisReason)
        return "wavelet, env mis: " + *m_envMisReason;
    return m_describe.empty() ? std::string(samplerKindName(m_kind)) : m_describe;
}

} // namespace wavelit::render
