// GLSL twin of blinn.cpp: D(h) = (n + 2)/(2π) cos^n θh, f = baseColor D / (4 max(cosθo, cosθi)),
// h sampled ∝ D cosθh and reflected; n = 2/α² − 2.
#ifndef WAVELIT_BLINN_GLSL
#define WAVELIT_BLINN_GLSL

#include "common/constants.glsl"
#include "cosine_power.glsl"

float blinnD(vec3 h, float n) {
    float x = (h.x * h.x + h.y * h.y) / (1.0 + h.z);
    return (n + 2.0) * (0.5 * kInvPi) * cosPowOneMinus(x, n);
}

vec3 blinnEval(vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    vec3 h = normalize(wo + wi);
    return baseColor * (blinnD(h, cosPowExponent(roughness)) / (4.0 * max(wo.z, wi.z)));
}

float blinnPdf(float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    vec3 h = normalize(wo + wi);
    return blinnD(h, cosPowExponent(roughness)) * h.z / (4.0 * dot(wo, h));
}

bool blinnSample(vec3 baseColor, float roughness, vec3 wo, float u1, float u2, out vec3 wi,
                 out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    float x = cosPowSampleOneMinusCos(u1, cosPowExponent(roughness) + 2.0);
    float sinT = sqrt(max(0.0, x * (2.0 - x)));
    float phi = 2.0 * kPi * u2;
    vec3 h = vec3(sinT * cos(phi), sinT * sin(phi), 1.0 - x);
    float woh = dot(wo, h);
    if (woh <= 0.0) return false; // a facet seen from behind reflects nothing
    wi = normalize(2.0 * woh * h - wo);
    if (wi.z <= 0.0) return false; // below the horizon: the path ends
    pdf = blinnPdf(roughness, wo, wi);
    f = blinnEval(baseColor, roughness, wo, wi);
    return pdf > 0.0;
}

#endif
