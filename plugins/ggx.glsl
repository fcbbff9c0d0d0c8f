// GLSL twin of ggx.cpp (docs/estimator.md "BRDFs"): GGX D, height-correlated Smith G2, Schlick F,
// visible-normal sampling (Heitz 2018), alpha = max(r^2, 1e-4). Same formulas in the same order;
// 1 - cos^2 is computed as x^2 + y^2 for the reason ggx.cpp gives (r = 0.02 near the mirror).
#ifndef WAVELIT_GGX_GLSL
#define WAVELIT_GGX_GLSL

#include "common/constants.glsl"

const float kGgxMinAlpha = 1e-4;

float ggxAlpha(float roughness) { return max(roughness * roughness, kGgxMinAlpha); }

float ggxD(vec3 h, float a2) {
    float d = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
    return a2 / (kPi * d * d);
}

float ggxLambda(vec3 w, float a2) {
    float tan2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5 * (-1.0 + sqrt(1.0 + a2 * tan2));
}

vec3 ggxSchlick(vec3 f0, float cosTheta) {
    float m = clamp(1.0 - cosTheta, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (vec3(1.0) - f0) * (m2 * m2 * m);
}

vec3 ggxSampleVisibleNormal(vec3 wo, float alpha, float u1, float u2) {
    vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float lensq = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) / sqrt(lensq) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u1);
    float phi = 2.0 * kPi * u2;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0, nh.z)));
}

vec3 ggxEval(vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    float a = ggxAlpha(roughness), a2 = a * a;
    vec3 h = normalize(wo + wi);
    float g2 = 1.0 / (1.0 + ggxLambda(wo, a2) + ggxLambda(wi, a2));
    vec3 f = ggxSchlick(baseColor, dot(wi, h));
    return ggxD(h, a2) * g2 * f / (4.0 * wo.z * wi.z);
}

float ggxPdf(float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    float a = ggxAlpha(roughness), a2 = a * a;
    vec3 h = normalize(wo + wi);
    float g1 = 1.0 / (1.0 + ggxLambda(wo, a2));
    return ggxD(h, a2) * g1 / (4.0 * wo.z);
}

bool ggxSample(vec3 baseColor, float roughness, vec3 wo, float u1, float u2, out vec3 wi,
               out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    vec3 h = ggxSampleVisibleNormal(wo, ggxAlpha(roughness), u1, u2);
    wi = 2.0 * dot(wo, h) * h - wo;
    if (wi.z <= 0.0) return false; // reflected below the horizon: the path ends
    // f and pdf from wi (not the sampled h), as ggx.cpp does, so pdf() reproduces it exactly.
    pdf = ggxPdf(roughness, wo, wi);
    f = ggxEval(baseColor, roughness, wo, wi);
    return pdf > 0.0;
}

#endif
