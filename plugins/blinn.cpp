// `blinn`: Blinn-Phong as a normalised distribution of half vectors,
//   D(h) = (n + 2)/(2π) cos^n θh  (∫ D cosθh dh = 1),   f = baseColor · D(h) / (4 max(cosθo, cosθi)),
// the max denominator of Ashikhmin and Shirley (2000) in place of a shadowing term: with wi
// reflected about h, dwi = 4 (wo·h) dh, so the albedo is at most ∫ D(h) (wo·h)⁺ dh ≤ 1 — unlike
// the common (n + 8)/(8π) cos^n θh, which reflects (n + 8)/(n + 1) > 1 at normal incidence. f is
// symmetric in wo and wi. Parameters: baseColor and roughness r with the exponent
// n = 2/α² − 2, α = max(r², 1e-4) (cosine_power.h); from an exponent n: r = (2 / (n + 2))^(1/4).
//
// Sampling: h ∝ D(h) cosθh (cosθh = (1 − u1)^(1/(n+2))), wi = reflect(−wo, h),
// pdf = D(h) cosθh / (4 wo·h); half vectors facing away from wo and wi below the horizon are
// invalid samples. GLSL twin: blinn.glsl.
#include "plugins/brdf.h"
#include "plugins/cosine_power.h"
#include "plugins/half_vector_sample.h"

#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace wavelit::plugins {
namespace {

using namespace cosine_power;

constexpr std::array<BrdfParameterInfo, 2> kParameters{{
    {"baseColor", "Specular colour", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(0.8f),
     "Reflectance of the lobe at normal incidence"},
    {"roughness", "Roughness", BrdfParameterType::Float, 0.0f, 1.0f, glm::vec3(0.5f),
     "Width of the highlight; exponent n = 2/r^4 - 2 (r = (2/(n+2))^(1/4) from an exponent)"},
}};

// D(h) for a unit h with h.z > 0; 1 − cosθh = sin²θh / (1 + cosθh) keeps it exact near the normal.
float blinnD(const glm::vec3& h, float n) {
    const float x = (h.x * h.x + h.y * h.y) / (1.0f + h.z);
    return (n + 2.0f) * (0.5f * util::kInvPi) * powOneMinus(x, n);
}

class Blinn final : public Brdf {
public:
    const char* name() const override { return "blinn"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfLobeAxis lobeAxis() const override { return BrdfLobeAxis::Mirror; }

    // D matches a Beckmann lobe of the same α, whose half vectors hold half their mass within
    // ~0.83 α and wi turns twice as fast: the GGX hint (ggx.cpp), 2 α and a 6 α cap.
    BrdfLobeWidth lobeWidth(const BrdfParams& p) const override {
        const double alpha = alphaOf(p.roughness);
        return {2.0 * alpha, 6.0 * alpha, BrdfTail::Gaussian};
    }

    BrdfGpuTwin gpuTwin() const override {
        return {"blinn.glsl", "blinnSample", "blinnEval", "blinnPdf"};
    }

    glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        const glm::vec3 h = glm::normalize(wo + wi);
        return p.baseColor * (blinnD(h, exponentOf(p.roughness)) / (4.0f * std::max(wo.z, wi.z)));
    }

    BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        if (wo.z <= 0.0f) return {};
        const float x = sampleOneMinusCos(u1, exponentOf(p.roughness) + 2.0f);
        const float sinT = std::sqrt(std::max(0.0f, x * (2.0f - x)));
        const float phi = 2.0f * util::kPi * u2;
        const glm::vec3 h(sinT * std::cos(phi), sinT * std::sin(phi), 1.0f - x);
        return reflectAboutHalfVector(*this, p, wo, h);
    }

    float pdf(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
        const glm::vec3 h = glm::normalize(wo + wi);
        return blinnD(h, exponentOf(p.roughness)) * h.z / (4.0f * glm::dot(wo, h));
    }

    std::optional<glm::vec2> invert(const BrdfParams& p, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
        const glm::vec3 h = glm::normalize(wo + wi);
        const float x = (h.x * h.x + h.y * h.y) / (1.0f + h.z);
        float phi = std::atan2(h.y, h.x);
        if (phi < 0.0f) phi += 2.0f * util::kPi;
        return glm::vec2(invertOneMinusCos(x, exponentOf(p.roughness) + 2.0f),
                         std::min(phi / (2.0f * util::kPi), 1.0f));
    }
};

} // namespace

const Brdf& blinnBrdf() {
    static const Blinn kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
