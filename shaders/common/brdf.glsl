// BRDF dispatch by material type code. The code is the plugin's registry index
// (plugins::brdfIndex, written per material by render/gpu/gpu_scene_data.cpp), and the dispatch
// that calls each plugin's GLSL twin (plugins/<name>.glsl) is generated from the registry when a
// kernel is compiled (render/gpu/brdf_shader_source.h), so no shader names a plugin:
//   bool  brdfSample(uint type, vec3 baseColor, float roughness, vec3 wo, float u1, float u2,
//                    out vec3 wi, out vec3 f, out float pdf)   // false: no valid sample
//   vec3  brdfEval(uint type, vec3 baseColor, float roughness, vec3 wo, vec3 wi) // f, no cosine
//   float brdfPdf(uint type, float roughness, vec3 wo, vec3 wi) // brdfSample's solid-angle pdf
// Local shading frame, z = normal; f without the cosine; pdf in solid angle (plugins/brdf.h).
// This file only makes a kernel compiled without the generated dispatch fail with a reason.
#ifndef WAVELIT_BRDF_GLSL
#define WAVELIT_BRDF_GLSL

#ifndef WAVELIT_BRDF_DISPATCH
#error "the BRDF dispatch is generated from the plugin registry: compile with render/gpu/brdf_shader_source.h"
#endif

#endif
