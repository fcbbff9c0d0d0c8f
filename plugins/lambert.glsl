// GLSL twin of lambert.cpp: f = baseColor / pi, cosine-weighted sampling through the concentric
// disk map (shaders/common/sampling.glsl), pdf = cos(theta) / pi. Local frame, z = normal.
// The signatures every twin shares (plugins/brdf.h: BrdfGpuTwin); roughness is unused here.
#ifndef WAVELIT_LAMBERT_GLSL
#define WAVELIT_LAMBERT_GLSL

#include "common/sampling.glsl"

vec3 lambertEval(vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    return baseColor * kInvPi;
}

float lambertPdf(float roughness, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0) return 0.0;
    return cosineHemispherePdf(wi);
}

bool lambertSample(vec3 baseColor, float roughness, vec3 wo, float u1, float u2, out vec3 wi,
                   out vec3 f, out float pdf) {
    wi = vec3(0.0, 0.0, 1.0);
    f = vec3(0.0);
    pdf = 0.0;
    if (wo.z <= 0.0) return false;
    wi = sampleCosineHemisphere(vec2(u1, u2));
    pdf = cosineHemispherePdf(wi);
    if (pdf <= 0.0) return false; // the disk's rim maps to the horizon
    f = baseColor * kInvPi;
    return true;
}

#endif
