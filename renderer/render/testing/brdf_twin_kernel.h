// The BRDF twin tests' kernel (gpu_brdf_twin_test, gpu_brdf_measured_twin_test): one invocation
// per case runs the generated dispatch's brdfSample, brdfEval and brdfPdf. in = (wo.xyz, u1),
// (baseColor.rgb, roughness — or a table offset for a table plugin), (u2, type, probe wi.xy);
// out = (wi.xyz, valid), (f.rgb, pdf), (eval at probe wi .rgb, pdf at probe wi). A table plugin's
// tables are bound where its compile options put WAVELIT_BRDF_TABLE_BINDING.
#pragma once

namespace wavelit::render {

inline constexpr const char* kBrdfTwinKernel = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/brdf.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 1) buffer Out { vec4 outputs[]; };
layout(push_constant) uniform Push { uint count; } pc;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    vec4 a = inputs[3 * i], b = inputs[3 * i + 1], c = inputs[3 * i + 2];
    uint type = uint(c.y);
    vec3 wi, f;
    float pdf;
    bool valid = brdfSample(type, b.rgb, b.a, a.xyz, a.w, c.x, wi, f, pdf);
    vec3 probe = vec3(c.z, c.w, sqrt(max(0.0, 1.0 - c.z * c.z - c.w * c.w)));
    vec3 fe = brdfEval(type, b.rgb, b.a, a.xyz, probe);
    float pe = brdfPdf(type, b.a, a.xyz, probe);
    outputs[3 * i] = vec4(wi, valid ? 1.0 : 0.0);
    outputs[3 * i + 1] = vec4(f, pdf);
    outputs[3 * i + 2] = vec4(fe, pe);
}
)";

} // namespace wavelit::render
