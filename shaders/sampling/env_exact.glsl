// The `env` technique with the radiance's own pdf (render/sampling/equirect_env_sampler.h is the
// CPU twin): an equirect texel by an inverse CDF over the rows and its row's CDF over the columns
// (render/sampling/guided_cdf.h: a guide table bounds each search to the entries one 1/n of the
// mass spans; monotone in u, so stratified passes give stratified draws), then a point uniform in
// solid angle inside it; the pdf is the texel's tabulated solid-angle pdf, read at the texel the
// radiance lookup reads (common/equirect.glsl). The tables sit in samplerWords at `offset`
// (gpu_sampler_data.h): width, height, each row's texel solid angle (height doubles, two words
// each: low, high), the rows' CDF (height + 1 doubles) and guide (height words), the rows' column
// CDFs (height x (width + 1) doubles) and guides (height x width words), then the texels' pdfs
// (height x width doubles, row-major). Each guide is padded to an even word count and `offset` is
// even (gpu_sampler_data.h GpuEnvExactLayout), so every double and the (width, height) pair sit on
// 8-byte boundaries and are read through samplerWords64, the u64 view of the same buffer: one
// load a lane instead of two on lavapipe (docs/performance.md "Lavapipe throughput (issue 12)").
#ifndef WAVELIT_ENV_EXACT_GLSL
#define WAVELIT_ENV_EXACT_GLSL

#include "common/constants.glsl"
#include "common/equirect.glsl"
#include "sampling/sampler_words.glsl"

// The double at (even) word i.
double envExactWord(uint i) { return uint64BitsToDouble(samplerPair(i >> 1u)); }

uvec2 envExactSize(uint offset) { return unpackUint2x32(samplerPair(offset >> 1u)); }

uint envEvenUp(uint n) { return (n + 1u) & ~1u; }

// In [lo, hi]: the first entry i of the CDF at word `cdf` with cdf[i + 1] > u.
uint envCdfFirstEndingAfter(uint cdf, uint lo, uint hi, double u) {
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (envExactWord(cdf + 2u * (mid + 1u)) > u)
            hi = mid;
        else
            lo = mid + 1u;
    }
    return lo;
}

// The entry u draws from the n entries of the guided CDF at words `cdf` (n + 1 doubles) and
// `guide` (n words), u rescaled into [0, 1) within it. The CPU's pickGuidedCdf, in the same double
// operations.
uint envCdfPick(uint cdf, uint guide, uint n, inout double u) {
    uint k = min(uint(u * double(n)), n - 1u);
    uint lo = envCdfFirstEndingAfter(cdf, max(samplerWord(guide + k), 1u) - 1u,
                                     min(k + 1u < n ? samplerWord(guide + k + 1u) + 1u : n - 1u, n - 1u), u);
    double c0 = envExactWord(cdf + 2u * lo), c1 = envExactWord(cdf + 2u * (lo + 1u));
    if (!(c0 <= u && u < c1)) {
        lo = envCdfFirstEndingAfter(cdf, 0u, n - 1u, u);
        c0 = envExactWord(cdf + 2u * lo);
        c1 = envExactWord(cdf + 2u * (lo + 1u));
    }
    double width = c1 - c0;
    u = width > 0.0LF ? clamp((u - c0) / width, 0.0LF, kBelowOneD) : 0.0LF;
    return lo;
}

// The *Sized functions take the tables' (width, height), envExactSize(offset), from a caller that
// has read it already: a pdf, a texel lookup and a draw at one vertex read it once, not three
// times (each is a per-lane load loop on lavapipe; the kernel writes other buffers, so the
// repeated loads are not left to Mesa to merge).
double envExactTexelPdfSized(uint offset, uvec2 size, uvec2 t) {
    uint pdfs = offset + 2u + 2u * size.y + 2u * (size.y + 1u) + envEvenUp(size.y) +
                2u * size.y * (size.x + 1u) + envEvenUp(size.y * size.x);
    return envExactWord(pdfs + 2u * (t.y * size.x + t.x));
}

double envExactTexelPdf(uint offset, uvec2 t) {
    return envExactTexelPdfSized(offset, envExactSize(offset), t);
}

// The texel world direction wi looks up (the radiance's texel too: the tables cover the map).
uvec2 envExactTexel(uint offset, vec3 wi, vec2 cosSinYaw) {
    return equirectTexelOf(wi, cosSinYaw, envExactSize(offset));
}

// Solid-angle pdf at world direction wi.
double envExactPdf(uint offset, vec3 wi, vec2 cosSinYaw) {
    uvec2 size = envExactSize(offset);
    return envExactTexelPdfSized(offset, size, equirectTexelOf(wi, cosSinYaw, size));
}

// An env-local direction.
vec3 envExactSampleSized(uint offset, uvec2 size, dvec2 u) {
    uint omega = offset + 2u, rowCdf = omega + 2u * size.y, rowGuide = rowCdf + 2u * (size.y + 1u);
    uint columnCdf = rowGuide + envEvenUp(size.y), columnGuide = columnCdf + 2u * size.y * (size.x + 1u);
    uint y = envCdfPick(rowCdf, rowGuide, size.y, u.y);
    uint x = envCdfPick(columnCdf + 2u * y * (size.x + 1u), columnGuide + y * size.x, size.x, u.x);
    float c0 = cos(kPi * float(y) / float(size.y));
    double drop = envExactWord(omega + 2u * y) * double(size.x) / double(2.0 * kPi);
    float cosTheta = clamp(float(double(c0) - drop * u.y), -1.0, 1.0);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * kPi * (float((double(x) + u.x) / double(size.x)) - 0.5);
    return vec3(sinTheta * cos(phi), cosTheta, sinTheta * sin(phi));
}

vec3 envExactSample(uint offset, dvec2 u) { return envExactSampleSized(offset, envExactSize(offset), u); }

#endif
