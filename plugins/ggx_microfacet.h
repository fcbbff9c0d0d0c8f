// The GGX microfacet pieces `ggx` and `glossy` share (docs/estimator.md "BRDFs"): D, the Smith
// Lambda of the height-correlated G2, Schlick's Fresnel and visible-normal sampling (Heitz 2018,
// JCGT 7(4)) with its inverse. alpha = max(r², 1e-4): the floor keeps D finite in float for r → 0.
// Numerics: 1 − cos²θ is x² + y² of the unit vector, never 1 − z² (see ggx.cpp).
// GLSL twin of these helpers: ggx.glsl (glossy.glsl includes it).
#pragma once

#include "plugins/brdf.h"

#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

namespace wavelit::plugins::ggx_detail {

inline constexpr float kMinAlpha = 1e-4f;

inline float alphaOf(const BrdfParams& p) { return std::max(p.roughness * p.roughness, kMinAlpha); }

// D(h) = α² / (π ((n·h)²(α² − 1) + 1)²), with (n·h)²(α² − 1) + 1 = x² + y² + α² z² for unit h.
inline float ggxD(const glm::vec3& h, float a2) {
    float d = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
    return a2 / (util::kPi * d * d);
}

// Λ(w) = (−1 + sqrt(1 + α² tan²θ)) / 2.
inline float smithLambda(const glm::vec3& w, float a2) {
    float tan2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5f * (-1.0f + std::sqrt(1.0f + a2 * tan2));
}

inline glm::vec3 schlick(const glm::vec3& f0, float cosTheta) {
    float m = std::clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (glm::vec3(1.0f) - f0) * (m2 * m2 * m);
}

// The frame of Heitz 2018's construction: wo stretched to the alpha = 1 configuration (vh) and
// two tangents. Shared by sampling and its inverse so both see the same frame.
struct VisibleFrame {
    glm::vec3 vh, t1, t2;
    VisibleFrame(const glm::vec3& wo, float alpha) {
        vh = glm::normalize(glm::vec3(alpha * wo.x, alpha * wo.y, wo.z));
        float lensq = vh.x * vh.x + vh.y * vh.y;
        t1 = lensq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq)
                          : glm::vec3(1.0f, 0.0f, 0.0f);
        t2 = glm::cross(vh, t1);
    }
};

// Heitz 2018, listing 1, isotropic alpha. Returns a microfacet normal with wo·h ≥ 0.
inline glm::vec3 sampleVisibleNormal(const glm::vec3& wo, float alpha, float u1, float u2) {
    VisibleFrame f(wo, alpha);
    float r = std::sqrt(u1);
    float phi = 2.0f * util::kPi * u2;
    float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    float s = 0.5f * (1.0f + f.vh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    glm::vec3 nh = p1 * f.t1 + p2 * f.t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * f.vh;
    return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

// Inverse of sampleVisibleNormal: unstretch h, express it in the (t1, t2, vh) frame, undo the
// projected-disk warp, then the polar map of (u1, u2).
inline std::optional<glm::vec2> invertVisibleNormal(const glm::vec3& wo, float alpha, const glm::vec3& h) {
    VisibleFrame f(wo, alpha);
    glm::vec3 nh = glm::normalize(glm::vec3(h.x / alpha, h.y / alpha, h.z));
    if (glm::dot(nh, f.vh) < 0.0f) return std::nullopt; // not a visible normal
    float p1 = glm::dot(nh, f.t1), p2 = glm::dot(nh, f.t2);
    float s = 0.5f * (1.0f + f.vh.z);
    p2 = (p2 - (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1))) / s;
    float phi = std::atan2(p2, p1);
    if (phi < 0.0f) phi += 2.0f * util::kPi;
    return glm::vec2(std::min(p1 * p1 + p2 * p2, 1.0f), std::min(phi / (2.0f * util::kPi), 1.0f));
}

// GgxLobe::eval at many wi (Brdf::evalBatch) with the reflectance R(cosθd) of `reflect`
// (reflect(c, r, g, b) writes R's channels): one branch-free loop the compiler vectorises (SSE2,
// four directions a step), the same operations in the same order as eval — so the same floats —
// with 0 selected where wi is at or below the horizon. The arrays are restrict parameters (GCC
// ignores restrict on local pointers and would otherwise version the loop on 15 alias checks).
template <class Reflect>
void evalLobeLoop(float a2, const glm::vec3& wo, size_t n, const float* __restrict x, const float* __restrict y,
                  const float* __restrict z, float* __restrict outR, float* __restrict outG,
                  float* __restrict outB, Reflect reflect) {
    const float onePlusLambdaO = 1.0f + smithLambda(wo, a2);
    const float fourCosO = 4.0f * wo.z;
    const float ox = wo.x, oy = wo.y, oz = wo.z;
    for (size_t i = 0; i < n; ++i) {
        const float wx = x[i], wy = y[i], wz = z[i];
        // h = normalize(wo + wi), as glm: v * (1 / sqrt(dot(v, v))).
        const float sx = ox + wx, sy = oy + wy, sz = oz + wz;
        const float inv = 1.0f / std::sqrt(sx * sx + sy * sy + sz * sz);
        const float hx = sx * inv, hy = sy * inv, hz = sz * inv;
        const float tan2 = (wx * wx + wy * wy) / (wz * wz);
        const float lambdaI = 0.5f * (-1.0f + std::sqrt(1.0f + a2 * tan2));
        const float g2 = 1.0f / (onePlusLambdaO + lambdaI);
        const float cosD = wx * hx + wy * hy + wz * hz;
        const float d = hx * hx + hy * hy + a2 * hz * hz;
        const float dg = a2 / (util::kPi * d * d) * g2;
        const float den = fourCosO * wz;
        float r, g, b;
        reflect(cosD, r, g, b);
        outR[i] = dg * r / den;
        outG[i] = dg * g / den;
        outB[i] = dg * b / den;
    }
    // eval's early 0 below the horizon, as a second pass and a bit mask (+0 there): selected in
    // the loop above, the lanes' work (inf / NaN there) would be sunk into the branch, and a
    // select here becomes a conditional store; either leaves the loop scalar.
    for (size_t i = 0; i < n; ++i) {
        const uint32_t keep = z[i] > 0.0f ? ~uint32_t(0) : 0u;
        outR[i] = std::bit_cast<float>(std::bit_cast<uint32_t>(outR[i]) & keep);
        outG[i] = std::bit_cast<float>(std::bit_cast<uint32_t>(outG[i]) & keep);
        outB[i] = std::bit_cast<float>(std::bit_cast<uint32_t>(outB[i]) & keep);
    }
}

template <class Reflect>
void evalLobeBatch(const BrdfParams& p, const glm::vec3& wo, const BrdfDirections& wi, const BrdfValues& out,
                   Reflect reflect) {
    if (wo.z <= 0.0f) {
        for (size_t i = 0; i < wi.count; ++i) out.r[i] = out.g[i] = out.b[i] = 0.0f;
        return;
    }
    const float a = alphaOf(p);
    evalLobeLoop(a * a, wo, wi.count, wi.x, wi.y, wi.z, out.r, out.g, out.b, reflect);
}

// Schlick's Fresnel for evalLobeBatch: schlick() per channel, with min / max for std::clamp
// (the same value for every finite cosine; they vectorise).
struct SchlickBatch {
    glm::vec3 f0;
    void operator()(float cosTheta, float& r, float& g, float& b) const {
        const float m = std::min(std::max(1.0f - cosTheta, 0.0f), 1.0f);
        const float m2 = m * m;
        const float m5 = m2 * m2 * m;
        r = f0.x + (1.0f - f0.x) * m5;
        g = f0.y + (1.0f - f0.y) * m5;
        b = f0.z + (1.0f - f0.z) * m5;
    }
};

// The microfacet lobe of `ggx` and `glossy`: f = D G2 R / (4 cosθo cosθi), where the
// reflectance R is the one thing they differ in (Schlick's Fresnel, or the colour alone).
class GgxLobe : public Brdf {
public:
    // R for the angle θd between wi and the half vector.
    virtual glm::vec3 reflectance(const BrdfParams& p, float cosThetaD) const = 0;

    BrdfLobeAxis lobeAxis() const override { return BrdfLobeAxis::Mirror; }

    // Half-width in wi: D(h) halves at theta_h ~ 0.64 alpha and wi turns twice as fast as h, so
    // ~1.3 alpha; 2 alpha keeps the shoulder. The cap is 3 half-widths (6 alpha): the oracle's
    // window, kept so its figures stay comparable across the variance study (docs/sampler-variance.md).
    // In double, as the samplers computed it before the traits existed.
    BrdfLobeWidth lobeWidth(const BrdfParams& p) const override {
        constexpr double kHalfWidthPerAlpha = 2.0;
        constexpr double kCapPerAlpha = 6.0;
        const double alpha = std::max(double(p.roughness) * p.roughness, 1e-4);
        return {kHalfWidthPerAlpha * alpha, kCapPerAlpha * alpha};
    }

    glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        float a = alphaOf(p), a2 = a * a;
        glm::vec3 h = glm::normalize(wo + wi);
        float g2 = 1.0f / (1.0f + smithLambda(wo, a2) + smithLambda(wi, a2));
        glm::vec3 f = reflectance(p, glm::dot(wi, h));
        return ggxD(h, a2) * g2 * f / (4.0f * wo.z * wi.z);
    }

    BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        BrdfSample s;
        if (wo.z <= 0.0f) return s;
        glm::vec3 h = sampleVisibleNormal(wo, alphaOf(p), u1, u2);
        s.wi = 2.0f * glm::dot(wo, h) * h - wo;
        if (s.wi.z <= 0.0f) return s; // reflected below the horizon: the path ends
        // f and pdf from wi (not the sampled h) so that pdf(wo, wi) reproduces this value exactly.
        s.pdf = pdf(p, wo, s.wi);
        s.f = eval(p, wo, s.wi);
        s.valid = s.pdf > 0.0f;
        return s;
    }

    float pdf(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
        float a = alphaOf(p), a2 = a * a;
        glm::vec3 h = glm::normalize(wo + wi);
        float g1 = 1.0f / (1.0f + smithLambda(wo, a2));
        return ggxD(h, a2) * g1 / (4.0f * wo.z);
    }

    std::optional<glm::vec2> invert(const BrdfParams& p, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
        return invertVisibleNormal(wo, alphaOf(p), glm::normalize(wo + wi));
    }
};

} // namespace wavelit::plugins::ggx_detail
