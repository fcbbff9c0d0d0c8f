// GLSL twin of phong.cpp: the modified Phong lobe (n + 2)/(2π) cos^n α about the mirror
// direction, n = max(2/α² − 2, 1), sampled as cos^n α; 1 − cos α as half the squared chord.
#ifndef WAVELIT_PHONG_GLSL
#define WAVELIT_PHONG_GLSL

#include "common/sampling.glsl"
#include "cosine_power.glsl"

vec3 phongMirror(vec3 wo) { return vec3(-wo.x, -wo.y, wo.z); }

// n >= 1 keeps the lobe continuous (phong.cpp).
float phongExponent(float roughness) { return max(cosPowExponent(roughness), 1.0); }

float phongOneMinusCos(vec3 wo, vec3 wi) {
    vec3 d = wi - phongMirror(wo);
    return 0.5 * dot(d, d);
}

vec3 phongEval(vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    float n = phongExponent(roughness);
    float lobe = cosPowOneMinus(phongOneMinusCos(wo, wi), n);
    return baseColor * ((n + 2.0) * (0.5 * kInvPi) * lobe);
}

float phongPdf(float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    float n = phongExponent(roughness);
    return (n + 1.0) * (0.5 * kInvPi) * cosPowOneMinus(phongOneMinusCos(wo, wi), n);
}

bool phongSample(vec3 baseColor, float roughness, vec3 wo, float u1, float u2, out vec3 wi,
                 out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    float m = phongExponent(roughness) + 1.0;
    float x = cosPowSampleOneMinusCos(u1, m);
    float sinA = sqrt(max(0.0, x * (2.0 - x)));
    float phi = 2.0 * kPi * u2;
    Frame fr = frameFromNormal(phongMirror(wo));
    wi = normalize(frameToWorld(fr, vec3(sinA * cos(phi), sinA * sin(phi), 1.0 - x)));
    if (wi.z <= 0.0) return false; // below the horizon: the path ends
    pdf = phongPdf(roughness, wo, wi);
    f = phongEval(baseColor, roughness, wo, wi);
    return pdf > 0.0;
}

#endif
