// `phong`: the modified, energy-conserving Phong lobe (Lafortune and Willems 1994):
//   f = baseColor · (n + 2)/(2π) · cos^n α,   α the angle between wi and the mirror direction of wo.
// The (n + 2)/(2π) normalisation makes the albedo exactly baseColor at normal incidence and less
// elsewhere (the lobe is cut by the horizon), so no setting creates energy; cos α is symmetric in
// wo and wi, so f is reciprocal. Specular lobe only: a Phong material's diffuse part is a
// `lambert` material. Parameters: baseColor (specular colour) and roughness r with the exponent
// n = max(2/α² − 2, 1), α = max(r², 1e-4) (cosine_power.h: the width of a Beckmann/GGX lobe of
// the same r). From an exponent n: r = (2 / (n + 2))^(1/4) (docs/brdfs.md). The floor n ≥ 1
// (r > 0.90 all alike) keeps the lobe continuous: cos^0 would be a step at 90° from the mirror.
//
// Sampling: cos^n α about the mirror direction, pdf = (n + 1)/(2π) cos^n α; directions below the
// horizon are invalid samples, so f·cos/pdf ≤ (n + 2)/(n + 1) · cosθi is bounded.
// GLSL twin: phong.glsl.
#include "plugins/brdf.h"
#include "plugins/cosine_power.h"

#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace wavelit::plugins {
namespace {

using namespace cosine_power;

float phongExponentOf(float roughness) { return std::max(exponentOf(roughness), 1.0f); }

constexpr std::array<BrdfParameterInfo, 2> kParameters{{
    {"baseColor", "Specular colour", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(0.8f),
     "Reflectance of the lobe at normal incidence"},
    {"roughness", "Roughness", BrdfParameterType::Float, 0.0f, 1.0f, glm::vec3(0.5f),
     "Width of the lobe; exponent n = 2/r^4 - 2 (r = (2/(n+2))^(1/4) from an exponent)"},
}};

glm::vec3 mirrorOf(const glm::vec3& wo) { return glm::vec3(-wo.x, -wo.y, wo.z); }

// 1 − wi·R as half the squared chord: exact in float near the mirror direction, and the same
// numbers for (wo, wi) and (wi, wo) (the chord's components only change sign).
float oneMinusCosToMirror(const glm::vec3& wo, const glm::vec3& wi) {
    const glm::vec3 d = wi - mirrorOf(wo);
    return 0.5f * glm::dot(d, d);
}

class Phong final : public Brdf {
public:
    const char* name() const override { return "phong"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfLobeAxis lobeAxis() const override { return BrdfLobeAxis::Mirror; }

    // cos^n about the mirror: half the samples lie within acos(0.5^(1/(n+1))) ≈ 0.83 α and 9 in
    // 10 within 1.52 α (n + 1 ≈ 2/α²) — half the width in wi of a Beckmann lobe of the same α,
    // whose half vector carries that width. 1.2 α and a 3 α cap hold the median and the tail.
    BrdfLobeWidth lobeWidth(const BrdfParams& p) const override {
        const double alpha = alphaOf(p.roughness);
        return {1.2 * alpha, 3.0 * alpha, BrdfTail::Gaussian};
    }

    BrdfGpuTwin gpuTwin() const override {
        return {"phong.glsl", "phongSample", "phongEval", "phongPdf"};
    }

    glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        const float n = phongExponentOf(p.roughness);
        const float lobe = powOneMinus(oneMinusCosToMirror(wo, wi), n);
        return p.baseColor * ((n + 2.0f) * (0.5f * util::kInvPi) * lobe);
    }

    BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        BrdfSample s;
        if (wo.z <= 0.0f) return s;
        const float m = phongExponentOf(p.roughness) + 1.0f;
        const float x = sampleOneMinusCos(u1, m);
        const float sinA = std::sqrt(std::max(0.0f, x * (2.0f - x)));
        const float phi = 2.0f * util::kPi * u2;
        const util::Frame f = util::Frame::fromNormal(mirrorOf(wo));
        s.wi = glm::normalize(f.toWorld(glm::vec3(sinA * std::cos(phi), sinA * std::sin(phi), 1.0f - x)));
        if (s.wi.z <= 0.0f) return s; // below the horizon: the path ends
        s.pdf = pdf(p, wo, s.wi);
        s.f = eval(p, wo, s.wi);
        s.valid = s.pdf > 0.0f;
        return s;
    }

    float pdf(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
        const float n = phongExponentOf(p.roughness);
        return (n + 1.0f) * (0.5f * util::kInvPi) * powOneMinus(oneMinusCosToMirror(wo, wi), n);
    }

    std::optional<glm::vec2> invert(const BrdfParams& p, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
        const util::Frame f = util::Frame::fromNormal(mirrorOf(wo));
        const glm::vec3 l = f.toLocal(wi);
        float phi = std::atan2(l.y, l.x);
        if (phi < 0.0f) phi += 2.0f * util::kPi;
        const float u1 = invertOneMinusCos(oneMinusCosToMirror(wo, wi), phongExponentOf(p.roughness) + 1.0f);
        return glm::vec2(u1, std::min(phi / (2.0f * util::kPi), 1.0f));
    }
};

} // namespace

const Brdf& phongBrdf() {
    static const Phong kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
