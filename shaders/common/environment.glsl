// Environment radiance, docs/estimator.md "Environment" (render/lights/cpu_environment.cpp is the CPU
// twin): rotate by -yaw about +Y, equirectangular (u, v) with v = 0 the top row, nearest texel.
// The texels live in a float buffer (3 floats each, row-major) that the including shader
// declares as `envTexels`.
#ifndef WAVELIT_ENVIRONMENT_GLSL
#define WAVELIT_ENVIRONMENT_GLSL

#include "common/constants.glsl"
#include "common/equirect.glsl"

// The three floats at i: from `envTexels`, or with WAVELIT_SCENE_TEXELS_BINDING its R32F texel
// view `envTexelView` (path_tracer.comp on CPU devices: lavapipe's texture path).
vec3 envTexelAt(uint i) {
#ifdef WAVELIT_SCENE_TEXELS_BINDING
    return vec3(texelFetch(envTexelView, int(i)).x, texelFetch(envTexelView, int(i + 1u)).x,
                texelFetch(envTexelView, int(i + 2u)).x);
#else
    return vec3(envTexels[i], envTexels[i + 1u], envTexels[i + 2u]);
#endif
}

// scale = intensity * tint; cosSinYaw = (cos yaw, sin yaw); envSize = (0, 0) for a constant env.
vec3 environmentRadiance(vec3 dir, vec3 scale, vec2 cosSinYaw, uvec2 envSize) {
    if (envSize.x == 0u || envSize.y == 0u) return scale;
    uvec2 t = equirectTexelOf(dir, cosSinYaw, envSize);
    uint tx = t.x, ty = t.y;
    uint i = 3u * (ty * envSize.x + tx);
    return envTexelAt(i) * scale;
}

#endif
