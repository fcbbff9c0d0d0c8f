// Environment radiance, docs/estimator.md "Environment" (render/lights/cpu_environment.cpp is the CPU
// twin): rotate by -yaw about +Y, equirectangular (u, v) with v = 0 the top row, nearest texel.
// The texels live in a float buffer (3 floats each, row-major) that the including shader
// declares as `envTexels`.
#ifndef WAVELIT_ENVIRONMENT_GLSL
#define WAVELIT_ENVIRONMENT_GLSL

#include "common/constants.glsl"

// scale = intensity * tint; cosSinYaw = (cos yaw, sin yaw); envSize = (0, 0) for a constant env.
vec3 environmentRadiance(vec3 dir, vec3 scale, vec2 cosSinYaw, uvec2 envSize) {
    if (envSize.x == 0u || envSize.y == 0u) return scale;
    float x = cosSinYaw.x * dir.x - cosSinYaw.y * dir.z;
    float z = cosSinYaw.y * dir.x + cosSinYaw.x * dir.z;
    float u = 0.5 + atan(z, x) / (2.0 * kPi);
    float v = acos(clamp(dir.y, -1.0, 1.0)) / kPi;
    float fx = u * float(envSize.x), fy = v * float(envSize.y);
    // The `> 0` tests send NaN to texel 0, as the CPU twin does.
    uint tx = fx > 0.0 ? min(uint(fx), envSize.x - 1u) : 0u;
    uint ty = fy > 0.0 ? min(uint(fy), envSize.y - 1u) : 0u;
    uint i = 3u * (ty * envSize.x + tx);
    return vec3(envTexels[i], envTexels[i + 1u], envTexels[i + 2u]) * scale;
}

#endif
