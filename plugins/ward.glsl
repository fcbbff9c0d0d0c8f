// GLSL twin of ward.cpp: Ward's lobe as Walter's notes normalise and sample it, with
// alpha_x = alpha / s, alpha_y = alpha s, s = sqrt(1 - 0.9 anisotropy). The anisotropy arrives
// as the first argument, decoded by the generated dispatch from the material's type code
// (plugins/brdf.h: BrdfGpuTwin::typeParameter).
#ifndef WAVELIT_WARD_GLSL
#define WAVELIT_WARD_GLSL

#include "common/constants.glsl"
#include "cosine_power.glsl"

vec2 wardAlphas(float anisotropy, float roughness) {
    float a = cosPowAlpha(roughness);
    float s = sqrt(1.0 - 0.9 * anisotropy);
    return vec2(a / s, a * s);
}

float wardExponent(vec3 h, vec2 a) {
    return (h.x * h.x / (a.x * a.x) + h.y * h.y / (a.y * a.y)) / (h.z * h.z);
}

vec3 wardEval(float anisotropy, vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    vec2 a = wardAlphas(anisotropy, roughness);
    vec3 h = normalize(wo + wi);
    float lobe = exp(-wardExponent(h, a));
    return baseColor * (lobe / (4.0 * kPi * a.x * a.y * sqrt(wo.z * wi.z)));
}

float wardPdf(float anisotropy, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    vec2 a = wardAlphas(anisotropy, roughness);
    vec3 h = normalize(wo + wi);
    float lobe = exp(-wardExponent(h, a));
    return lobe / (4.0 * kPi * a.x * a.y * dot(wi, h) * h.z * h.z * h.z);
}

bool wardSample(float anisotropy, vec3 baseColor, float roughness, vec3 wo, float u1, float u2,
                out vec3 wi, out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    vec2 a = wardAlphas(anisotropy, roughness);
    float psi = 2.0 * kPi * u2;
    float px = a.x * cos(psi), py = a.y * sin(psi);
    float len = sqrt(px * px + py * py);
    float c = px / len, sn = py / len; // the direction of atan(αy/αx tan 2πu2), without atan
    float tan2 = -log(1.0 - u1) / (c * c / (a.x * a.x) + sn * sn / (a.y * a.y));
    float cosT = 1.0 / sqrt(1.0 + tan2);
    float sinT = sqrt(tan2) * cosT;
    vec3 h = vec3(sinT * c, sinT * sn, cosT);
    float woh = dot(wo, h);
    if (woh <= 0.0) return false; // a facet seen from behind reflects nothing
    wi = normalize(2.0 * woh * h - wo);
    if (wi.z <= 0.0) return false; // below the horizon: the path ends
    pdf = wardPdf(anisotropy, roughness, wo, wi);
    f = wardEval(anisotropy, baseColor, roughness, wo, wi);
    return pdf > 0.0;
}

#endif
