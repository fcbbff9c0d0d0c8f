// The `env` technique with the radiance's own pdf (render/sampling/equirect_env_sampler.h is the
// CPU twin): an equirect texel by an alias table over the rows and its row's alias table over the
// columns (O(1): no search), then a point uniform in solid angle inside it; the pdf is the texel's
// tabulated solid-angle pdf, read at the texel the radiance lookup reads (common/equirect.glsl).
// The tables sit in samplerWords at `offset` (gpu_sampler_data.h): width, height, then each row's
// texel solid angle (height doubles, two words each: low, high), the row alias table (height
// slots) and the rows' column alias tables (height x width slots), two words a slot (threshold
// float bits, alias), then the texels' pdfs (height x width doubles, row-major).
#ifndef WAVELIT_ENV_EXACT_GLSL
#define WAVELIT_ENV_EXACT_GLSL

#include "common/constants.glsl"
#include "common/equirect.glsl"

double envExactWord(uint i) { return packDouble2x32(uvec2(samplerWords[i], samplerWords[i + 1u])); }

uvec2 envExactSize(uint offset) { return uvec2(samplerWords[offset], samplerWords[offset + 1u]); }

// The entry of the n slots at word `base` that u draws: the slot by u n, its coin by the
// remainder (keep the slot's entry below its threshold, else take its alias); u rescaled into
// [0, 1) within what was chosen. The CPU's pick(), in the same double operations.
uint envExactPick(uint base, uint n, inout double u) {
    double s = u * double(n);
    uint i = min(uint(s), n - 1u);
    double f = s - double(i);
    double q = double(uintBitsToFloat(samplerWords[base + 2u * i]));
    if (f < q) {
        u = min(f / q, kBelowOneD);
        return i;
    }
    u = min((f - q) / (1.0LF - q), kBelowOneD);
    return samplerWords[base + 2u * i + 1u];
}

double envExactTexelPdf(uint offset, uvec2 t) {
    uvec2 size = envExactSize(offset);
    uint pdfs = offset + 2u + 2u * size.y + 2u * size.y + 2u * size.y * size.x;
    return envExactWord(pdfs + 2u * (t.y * size.x + t.x));
}

// The texel world direction wi looks up (the radiance's texel too: the tables cover the map).
uvec2 envExactTexel(uint offset, vec3 wi, vec2 cosSinYaw) {
    return equirectTexelOf(wi, cosSinYaw, envExactSize(offset));
}

// Solid-angle pdf at world direction wi.
double envExactPdf(uint offset, vec3 wi, vec2 cosSinYaw) {
    return envExactTexelPdf(offset, envExactTexel(offset, wi, cosSinYaw));
}

// An env-local direction.
vec3 envExactSample(uint offset, dvec2 u) {
    uvec2 size = envExactSize(offset);
    uint omega = offset + 2u, rows = omega + 2u * size.y, columns = rows + 2u * size.y;
    uint y = envExactPick(rows, size.y, u.y);
    uint x = envExactPick(columns + 2u * y * size.x, size.x, u.x);
    float c0 = cos(kPi * float(y) / float(size.y));
    double drop = envExactWord(omega + 2u * y) * double(size.x) / double(2.0 * kPi);
    float cosTheta = clamp(float(double(c0) - drop * u.y), -1.0, 1.0);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * kPi * (float((double(x) + u.x) / double(size.x)) - 0.5);
    return vec3(sinTheta * cos(phi), cosTheta, sinTheta * sin(phi));
}

#endif
