// ProductWindow's GLSL side (render/sampling/sampler_window.h): the part of the octahedral square
// a product covers, a square of side 2^-k whose origin (ox, oy) is in units of 2^-(k+1).
#ifndef WAVELIT_SAMPLER_WINDOW_GLSL
#define WAVELIT_SAMPLER_WINDOW_GLSL

#include "common/constants.glsl"
#include "common/octahedral.glsl"

// The smallest window (k <= maxK) holding the octahedral image of the cap of half-angle
// `halfAngle` around `axis` (env-local): render::chooseWindow's twin, probing WAVELIT_RIM_PROBES
// points on the cap's edge and on a ring at WAVELIT_RIM_INNER_RING of its angle; an image wider than
// WAVELIT_MAX_COMPACT_EXTENT of the square gets the whole square.
void dsChooseWindow(vec3 axis, float halfAngle, int maxK, out int k, out int ox, out int oy) {
    k = 0;
    ox = 0;
    oy = 0;
    if (halfAngle >= WAVELIT_WHOLE_SPHERE_CAP_ANGLE || maxK < 1) return;
    vec3 a = normalize(axis);
    vec3 helper = abs(a.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 t = normalize(cross(helper, a));
    vec3 b = cross(a, t);
    vec2 lo = octToSquare(a), hi = lo;
    for (int ring = 0; ring < 2; ++ring) {
        float theta = (ring == 0 ? 1.0 : WAVELIT_RIM_INNER_RING) * halfAngle;
        for (int i = 0; i < WAVELIT_RIM_PROBES; ++i) {
            float phi = 2.0 * kPi * float(i) / float(WAVELIT_RIM_PROBES);
            vec3 d = cos(theta) * a + sin(theta) * (cos(phi) * t + sin(phi) * b);
            vec2 p = octToSquare(d);
            lo = min(lo, p);
            hi = max(hi, p);
        }
    }
    if (hi.x - lo.x > WAVELIT_MAX_COMPACT_EXTENT || hi.y - lo.y > WAVELIT_MAX_COMPACT_EXTENT) return;
    for (int kk = maxK; kk >= 1; --kk) {
        double side = 1.0LF / double(1 << kk), halfSide = 0.5LF * side;
        int maxOrigin = (1 << (kk + 1)) - 2;
        int x0 = clamp(int(floor(double(lo.x) / halfSide)), 0, maxOrigin);
        int y0 = clamp(int(floor(double(lo.y) / halfSide)), 0, maxOrigin);
        if (double(x0) * halfSide + side >= double(hi.x) && double(y0) * halfSide + side >= double(hi.y)) {
            k = kk;
            ox = x0;
            oy = y0;
            return;
        }
    }
}

#endif
