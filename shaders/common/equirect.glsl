// The equirect texel a world direction looks up, docs/estimator.md "Environment": rotate by -yaw
// about +Y, (u, v) with v = 0 the top row, nearest texel (render/lights/cpu_environment.cpp is the
// CPU twin). Shared by the radiance lookup (common/environment.glsl) and the exact env pdf
// (sampling/env_exact.glsl), so both read the same texel.
#ifndef WAVELIT_EQUIRECT_GLSL
#define WAVELIT_EQUIRECT_GLSL

#include "common/constants.glsl"

uvec2 equirectTexelOf(vec3 dir, vec2 cosSinYaw, uvec2 envSize) {
    float x = cosSinYaw.x * dir.x - cosSinYaw.y * dir.z;
    float z = cosSinYaw.y * dir.x + cosSinYaw.x * dir.z;
    float u = 0.5 + atan(z, x) / (2.0 * kPi);
    // acos through atan, as lights.glsl does: Mesa's acos is a short polynomial (~1e-4 rad), which
    // put ~0.3% of directions in the row beside the CPU's; its atan is accurate to ~1e-6.
    float c = clamp(dir.y, -1.0, 1.0);
    float v = atan(sqrt(max(0.0, (1.0 - c) * (1.0 + c))), c) / kPi;
    float fx = u * float(envSize.x), fy = v * float(envSize.y);
    // The `> 0` tests send NaN to texel 0, as the CPU twin does.
    uint tx = fx > 0.0 ? min(uint(fx), envSize.x - 1u) : 0u;
    uint ty = fy > 0.0 ? min(uint(fy), envSize.y - 1u) : 0u;
    return uvec2(tx, ty);
}

#endif
