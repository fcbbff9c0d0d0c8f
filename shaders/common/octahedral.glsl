// The equal-area octahedral map of the sampler tables, twin of wavelet::OctahedralMap
// (renderer/wavelet/sphere_map.cpp: pbrt-v4's EqualAreaSquareToSphere and its inverse, with our
// axes: the map's z is our +Y). Float: GLSL has no double trigonometry. Callers that must locate
// a SAMPLED point exactly keep the point itself (double) instead of re-deriving it from the
// direction (direction_sampler.glsl explains why).
#ifndef WAVELIT_OCTAHEDRAL_GLSL
#define WAVELIT_OCTAHEDRAL_GLSL

#include "common/constants.glsl"

vec3 octToDirection(vec2 uv) {
    float u = 2.0 * uv.x - 1.0, v = 2.0 * uv.y - 1.0;
    float up = abs(u), vp = abs(v);
    float sd = 1.0 - (up + vp);
    float r = 1.0 - abs(sd);
    float phi = (r == 0.0 ? 1.0 : (vp - up) / r + 1.0) * (kPi / 4.0);
    float z = (sd < 0.0 ? -1.0 : 1.0) * (1.0 - r * r);
    float s = r * sqrt(max(0.0, 2.0 - r * r));
    float x = (u < 0.0 ? -1.0 : 1.0) * abs(cos(phi)) * s;
    float y = (v < 0.0 ? -1.0 : 1.0) * abs(sin(phi)) * s;
    return normalize(vec3(x, z, y));
}

// Square point of a unit direction, in [0, 1)^2 (the last texel owns the edge, as
// render::octSquarePoint).
vec2 octToSquare(vec3 direction) {
    vec3 d = normalize(direction);
    float dx = d.x, dy = d.z, dz = d.y;
    float x = abs(dx), y = abs(dy), z = abs(dz);
    float r = sqrt(max(0.0, 1.0 - z));
    float a = max(x, y);
    float b = min(x, y);
    b = a == 0.0 ? 0.0 : b / a;
    float phi = atan(b) * (2.0 / kPi);
    if (x < y) phi = 1.0 - phi;
    float v = phi * r, u = r - v;
    if (dz < 0.0) {
        float t = u;
        u = 1.0 - v;
        v = 1.0 - t;
    }
    u = dx < 0.0 ? -u : u;
    v = dy < 0.0 ? -v : v;
    const float kBelowOne = 0.99999994; // largest float below 1
    return clamp(0.5 * (vec2(u, v) + 1.0), vec2(0.0), vec2(kBelowOne));
}

#endif
