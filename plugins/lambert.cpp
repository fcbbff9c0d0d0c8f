// `lambert`: ideal diffuse reflection, f = baseColor / π, sampled cosine-weighted through the
// concentric disk map so f·cosθ/pdf = baseColor exactly (zero variance for the BRDF factor).
// Parameters: baseColor (albedo, each channel in [0, 1]). GLSL twin: lambert.glsl.
#include "plugins/brdf.h"

#include "util/hemisphere_sampling.h"

#include <array>
#include <numbers>

namespace wavelit::plugins {
namespace {

constexpr std::array<BrdfParameterInfo, 1> kParameters{{
    {"baseColor", "Base colour", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(0.8f),
     "Diffuse albedo: the fraction of light reflected, per channel"},
}};

// out = f where z > 0, else 0; restrict parameters, so GCC vectorises it without alias checks.
void selectAbove(const glm::vec3& f, size_t n, const float* __restrict z, float* __restrict r, float* __restrict g,
                 float* __restrict b) {
    for (size_t i = 0; i < n; ++i) {
        const bool above = z[i] > 0.0f;
        r[i] = above ? f.x : 0.0f;
        g[i] = above ? f.y : 0.0f;
        b[i] = above ? f.z : 0.0f;
    }
}

class Lambert final : public Brdf {
public:
    const char* name() const override { return "lambert"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfLobeAxis lobeAxis() const override { return BrdfLobeAxis::Normal; }

    // The clamped cosine about the normal: a half-width of pi/2 and, since the whole hemisphere
    // holds it, a cap past pi (3.2 rad: the oracle then covers the whole sphere).
    BrdfLobeWidth lobeWidth(const BrdfParams&) const override {
        return {0.5 * std::numbers::pi, 3.2};
    }

    BrdfGpuTwin gpuTwin() const override {
        return {"lambert.glsl", "lambertSample", "lambertEval", "lambertPdf"};
    }

    glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        return p.baseColor * util::kInvPi;
    }

    // eval per direction: f is constant above the horizon, so this is a select per entry.
    void evalBatch(const BrdfParams& p, const glm::vec3& wo, const BrdfDirections& wi,
                   const BrdfValues& out) const override {
        const glm::vec3 f = wo.z <= 0.0f ? glm::vec3(0.0f) : p.baseColor * util::kInvPi;
        selectAbove(f, wi.count, wi.z, out.r, out.g, out.b);
    }

    BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        BrdfSample s;
        if (wo.z <= 0.0f) return s;
        s.wi = util::sampleCosineHemisphere(glm::vec2(u1, u2));
        s.pdf = util::cosineHemispherePdf(s.wi);
        if (s.pdf <= 0.0f) return s; // the disk's rim maps to the horizon: invalid
        s.f = p.baseColor * util::kInvPi;
        s.valid = true;
        return s;
    }

    float pdf(const BrdfParams&, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f) return 0.0f;
        return util::cosineHemispherePdf(wi);
    }

    std::optional<glm::vec2> invert(const BrdfParams&, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
        return util::invertCosineHemisphere(wi);
    }
};

} // namespace

const Brdf& lambertBrdf() {
    static const Lambert kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
