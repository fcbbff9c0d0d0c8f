// GLSL twin of glossy.cpp: GGX D and height-correlated G2 (from ggx.glsl) with the colour in
// place of Fresnel; visible-normal sampling as ggx.
#ifndef WAVELIT_GLOSSY_GLSL
#define WAVELIT_GLOSSY_GLSL

#include "ggx.glsl"

vec3 glossyEval(vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    float a = ggxAlpha(roughness), a2 = a * a;
    vec3 h = normalize(wo + wi);
    float g2 = 1.0 / (1.0 + ggxLambda(wo, a2) + ggxLambda(wi, a2));
    return ggxD(h, a2) * g2 * baseColor / (4.0 * wo.z * wi.z);
}

float glossyPdf(float roughness, vec3 wo, vec3 wi) { return ggxPdf(roughness, wo, wi); }

bool glossySample(vec3 baseColor, float roughness, vec3 wo, float u1, float u2, out vec3 wi,
                  out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    vec3 h = ggxSampleVisibleNormal(wo, ggxAlpha(roughness), u1, u2);
    wi = 2.0 * dot(wo, h) * h - wo;
    if (wi.z <= 0.0) return false; // reflected below the horizon: the path ends
    pdf = ggxPdf(roughness, wo, wi);
    f = glossyEval(baseColor, roughness, wo, wi);
    return pdf > 0.0;
}

#endif
