// Hemisphere sampling and the shading frame, twins of renderer/util/hemisphere_sampling.cpp
// (same formulas in the same order, so the same (u1, u2) gives the same direction up to rounding).
#ifndef WAVELIT_SAMPLING_GLSL
#define WAVELIT_SAMPLING_GLSL

#include "common/constants.glsl"

// Shirley-Chiu concentric map: unit square -> unit disk, area preserving.
vec2 sampleConcentricDisk(vec2 u) {
    vec2 o = 2.0 * u - vec2(1.0);
    if (o.x == 0.0 && o.y == 0.0) return vec2(0.0);
    float r, theta;
    if (abs(o.x) > abs(o.y)) {
        r = o.x;
        theta = (kPi / 4.0) * (o.y / o.x);
    } else {
        r = o.y;
        theta = kPi / 2.0 - (kPi / 4.0) * (o.x / o.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

vec3 sampleCosineHemisphere(vec2 u) {
    vec2 d = sampleConcentricDisk(u);
    float z = sqrt(max(0.0, 1.0 - d.x * d.x - d.y * d.y));
    return vec3(d.x, d.y, z);
}

float cosineHemispherePdf(vec3 w) { return w.z > 0.0 ? w.z * kInvPi : 0.0; }

// Orthonormal basis from a unit normal (Duff et al. 2017), as util::Frame::fromNormal.
struct Frame {
    vec3 t, b, n;
};

Frame frameFromNormal(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    Frame f;
    f.t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    f.b = vec3(b, s + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

vec3 frameToLocal(Frame f, vec3 w) { return vec3(dot(f.t, w), dot(f.b, w), dot(f.n, w)); }
vec3 frameToWorld(Frame f, vec3 w) { return w.x * f.t + w.y * f.b + w.z * f.n; }

#endif
