// `ward`: Ward's anisotropic Gaussian lobe in the form Walter's notes normalise and sample
// (B. Walter 2005, "Notes on the Ward BRDF", Cornell PCG-05-06):
//   f = baseColor · exp(−tan²θh (cos²φh/αx² + sin²φh/αy²)) / (4π αx αy sqrt(cosθo cosθi)),
//   pdf(wi) = exp(−…) / (4π αx αy (wi·h) cos³θh)  (h drawn by Walter's eqs. 6–7, then reflected).
// f is symmetric in wo and wi. The sqrt(cosθo cosθi) denominator loses energy at grazing views
// (the albedo falls towards cosθo), never creates it. Parameters: baseColor, roughness r with
// α = max(r², 1e-4), and anisotropy a in [0, 1]: αx = α / s, αy = α · s with s = sqrt(1 − 0.9 a)
// (Burley 2012's stretch), along the shading frame's tangent (the x axis of the frame both
// tracers build from the normal). a = 0 is isotropic Ward.
//
// On the GPU the anisotropy rides in the material's type code, in steps of 1/4096
// (brdf.h: BrdfGpuTwin::typeParameter); this plugin rounds it the same way so both tracers
// compute the same lobe. GLSL twin: ward.glsl.
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

constexpr std::array<BrdfParameterInfo, 3> kParameters{{
    {"baseColor", "Specular colour", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(0.8f),
     "Specular reflectance of the lobe (Ward rho_s)"},
    {"roughness", "Roughness", BrdfParameterType::Float, 0.0f, 1.0f, glm::vec3(0.5f),
     "Lobe width r; Ward alpha = r^2 (alpha_x = alpha_y when anisotropy is 0)"},
    {"anisotropy", "Anisotropy", BrdfParameterType::Float, 0.0f, 1.0f, glm::vec3(0.0f),
     "0 is isotropic; towards 1 the highlight stretches along the surface tangent"},
}};

struct Alphas {
    float x, y;
};

Alphas alphasOf(const BrdfParams& p) {
    const float a = cosine_power::alphaOf(p.roughness);
    const float s = std::sqrt(1.0f - 0.9f * brdfTypeParameterStep(p.anisotropy));
    return {a / s, a * s};
}

// tan²θh (cos²φh/αx² + sin²φh/αy²) = (hx²/αx² + hy²/αy²) / hz² for a unit h.
float wardExponent(const glm::vec3& h, const Alphas& a) {
    return (h.x * h.x / (a.x * a.x) + h.y * h.y / (a.y * a.y)) / (h.z * h.z);
}

class Ward final : public Brdf {
public:
    const char* name() const override { return "ward"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfLobeAxis lobeAxis() const override { return BrdfLobeAxis::Mirror; }

    // A Beckmann-like lobe as GGX's hint (ggx.cpp) with the wider of the two alphas: half the
    // half vectors within ~0.83 α, wi turning twice as fast.
    BrdfLobeWidth lobeWidth(const BrdfParams& p) const override {
        const Alphas a = alphasOf(p);
        const double alpha = std::max(a.x, a.y);
        return {2.0 * alpha, 6.0 * alpha, BrdfTail::Gaussian};
    }

    BrdfGpuTwin gpuTwin() const override {
        BrdfGpuTwin t{"ward.glsl", "wardSample", "wardEval", "wardPdf"};
        t.typeParameter = [](const BrdfParams& p) { return p.anisotropy; };
        return t;
    }

    glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        const Alphas a = alphasOf(p);
        const glm::vec3 h = glm::normalize(wo + wi);
        const float lobe = std::exp(-wardExponent(h, a));
        return p.baseColor * (lobe / (4.0f * util::kPi * a.x * a.y * std::sqrt(wo.z * wi.z)));
    }

    BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        if (wo.z <= 0.0f) return {};
        const Alphas a = alphasOf(p);
        // Walter's eq. 7, φh = atan(αy/αx tan 2πu2) in the quadrant of 2πu2, taken as the
        // direction of (αx cos 2πu2, αy sin 2πu2): no atan, whose Mesa GLSL form is a short
        // polynomial (docs/estimator.md) that moved sampled directions by ~1e-4.
        const float psi = 2.0f * util::kPi * u2;
        const float px = a.x * std::cos(psi), py = a.y * std::sin(psi);
        const float len = std::sqrt(px * px + py * py);
        const float c = px / len, sn = py / len;
        const float tan2 = -std::log(1.0f - u1) / (c * c / (a.x * a.x) + sn * sn / (a.y * a.y));
        const float cosT = 1.0f / std::sqrt(1.0f + tan2);
        const float sinT = std::sqrt(tan2) * cosT;
        const glm::vec3 h(sinT * c, sinT * sn, cosT);
        return reflectAboutHalfVector(*this, p, wo, h);
    }

    float pdf(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
        const Alphas a = alphasOf(p);
        const glm::vec3 h = glm::normalize(wo + wi);
        const float lobe = std::exp(-wardExponent(h, a));
        return lobe / (4.0f * util::kPi * a.x * a.y * glm::dot(wi, h) * h.z * h.z * h.z);
    }

    std::optional<glm::vec2> invert(const BrdfParams& p, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
        const Alphas a = alphasOf(p);
        const glm::vec3 h = glm::normalize(wo + wi);
        const float phi = std::atan2(h.y, h.x);
        float psi = std::atan2(a.x * std::sin(phi), a.y * std::cos(phi));
        if (psi < 0.0f) psi += 2.0f * util::kPi;
        const float u1 = -std::expm1(-wardExponent(h, a));
        return glm::vec2(std::clamp(u1, 0.0f, 1.0f), std::min(psi / (2.0f * util::kPi), 1.0f));
    }
};

} // namespace

const Brdf& wardBrdf() {
    static const Ward kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
