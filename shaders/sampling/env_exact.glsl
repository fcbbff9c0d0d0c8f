// The `env` technique with the radiance's own pdf (render/sampling/equirect_env_sampler.h is the
// CPU twin): an equirect texel by a marginal CDF over rows and a conditional CDF in its row,
// then a point uniform in solid angle inside it; the pdf is the texel's probability over its
// solid angle, read at the texel the radiance lookup reads (common/equirect.glsl).
// The tables sit in samplerWords at `offset` (gpu_sampler_data.h): width, height, then doubles as
// two words each (low, high): the marginal CDF (height + 1), each row's texel solid angle
// (height), the rows' conditional CDFs (height x (width + 1)).
#ifndef WAVELIT_ENV_EXACT_GLSL
#define WAVELIT_ENV_EXACT_GLSL

#include "common/constants.glsl"
#include "common/equirect.glsl"

double envExactWord(uint i) { return packDouble2x32(uvec2(samplerWords[i], samplerWords[i + 1u])); }

uvec2 envExactSize(uint offset) { return uvec2(samplerWords[offset], samplerWords[offset + 1u]); }

// Interval i of the CDF at word `base` (n + 1 doubles) with cdf[i] <= u < cdf[i + 1], never an
// empty one (std::upper_bound - 1 on the CPU); u rescaled into the interval.
uint envExactPick(uint base, uint n, inout double u) {
    uint lo = 0u, hi = n - 1u;
    while (lo < hi) {
        uint mid = (lo + hi + 1u) >> 1;
        if (envExactWord(base + 2u * mid) <= u) lo = mid;
        else hi = mid - 1u;
    }
    double c0 = envExactWord(base + 2u * lo), width = envExactWord(base + 2u * lo + 2u) - c0;
    u = width > 0.0LF ? min((u - c0) / width, kBelowOneD) : 0.5LF;
    return lo;
}

double envExactTexelPdf(uint offset, uvec2 t) {
    uvec2 size = envExactSize(offset);
    uint marginal = offset + 2u, omega = marginal + 2u * (size.y + 1u);
    uint row = omega + 2u * size.y + 2u * t.y * (size.x + 1u);
    double p = (envExactWord(marginal + 2u * t.y + 2u) - envExactWord(marginal + 2u * t.y)) *
               (envExactWord(row + 2u * t.x + 2u) - envExactWord(row + 2u * t.x));
    return p / envExactWord(omega + 2u * t.y);
}

// Solid-angle pdf at world direction wi.
double envExactPdf(uint offset, vec3 wi, vec2 cosSinYaw) {
    return envExactTexelPdf(offset, equirectTexelOf(wi, cosSinYaw, envExactSize(offset)));
}

// An env-local direction.
vec3 envExactSample(uint offset, dvec2 u) {
    uvec2 size = envExactSize(offset);
    uint marginal = offset + 2u, omega = marginal + 2u * (size.y + 1u);
    uint y = envExactPick(marginal, size.y, u.y);
    uint x = envExactPick(omega + 2u * size.y + 2u * y * (size.x + 1u), size.x, u.x);
    float c0 = cos(kPi * float(y) / float(size.y));
    double drop = envExactWord(omega + 2u * y) * double(size.x) / double(2.0 * kPi);
    float cosTheta = clamp(float(double(c0) - drop * u.y), -1.0, 1.0);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * kPi * (float((double(x) + u.x) / double(size.x)) - 0.5);
    return vec3(sinTheta * cos(phi), cosTheta, sinTheta * sin(phi));
}

#endif
