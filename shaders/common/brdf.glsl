// BRDF dispatch by material type: the GLSL twins in plugins/<name>.glsl, selected by the type
// code the GPU driver writes per material (render/gpu/gpu_scene_data.h: kBrdfLambert, kBrdfGgx).
// Local shading frame, z = normal; f without the cosine; pdf in solid angle (plugins/brdf.h).
#ifndef WAVELIT_BRDF_GLSL
#define WAVELIT_BRDF_GLSL

#include "lambert.glsl"
#include "ggx.glsl"

const uint kBrdfLambert = 0u;
const uint kBrdfGgx = 1u;

bool brdfSample(uint type, vec3 baseColor, float roughness, vec3 wo, float u1, float u2,
                out vec3 wi, out vec3 f, out float pdf) {
    if (type == kBrdfGgx) return ggxSample(baseColor, roughness, wo, u1, u2, wi, f, pdf);
    return lambertSample(baseColor, wo, u1, u2, wi, f, pdf);
}

// f(wo, wi) without the cosine (next-event estimation).
vec3 brdfEval(uint type, vec3 baseColor, float roughness, vec3 wo, vec3 wi) {
    if (type == kBrdfGgx) return ggxEval(baseColor, roughness, wo, wi);
    return lambertEval(baseColor, wo, wi);
}

// Solid-angle pdf with which brdfSample draws wi (MIS weights).
float brdfPdf(uint type, float roughness, vec3 wo, vec3 wi) {
    if (type == kBrdfGgx) return ggxPdf(roughness, wo, wi);
    return lambertPdf(wo, wi);
}

#endif
