// The random numbers of one path: shuffled, Owen-scrambled Sobol' points per draw group, indexed
// by the pass. The same code as renderer/util/path_sampler.h (read its comment for why), so the
// GPU and CPU tracers draw the same numbers for the same (seed key, pixel, pass).
#ifndef WAVELIT_PATH_SAMPLER_GLSL
#define WAVELIT_PATH_SAMPLER_GLSL

struct PathSampler {
    uint pixelSeed;
    uint pass;
    uint group;
};

uint psHash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

uint psOwenScramble(uint x, uint seed) {
    x = bitfieldReverse(x);
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return bitfieldReverse(x);
}

// util::sobol2D: van der Corput and the Pascal matrix mod 2 applied to it (five shift-xors).
uvec2 psSobol2D(uint index) {
    uint x = bitfieldReverse(index), y = x;
    y ^= (y & 0x55555555u) << 1;
    y ^= (y & 0x33333333u) << 2;
    y ^= (y & 0x0F0F0F0Fu) << 4;
    y ^= (y & 0x00FF00FFu) << 8;
    y ^= (y & 0x0000FFFFu) << 16;
    return uvec2(x, y);
}

PathSampler psStart(uint seedKey, uint pixelIndex, uint pass) {
    PathSampler s;
    s.pixelSeed = psHash(pixelIndex ^ seedKey);
    s.pass = pass;
    s.group = 0u;
    return s;
}

uvec2 psNextPoint(inout PathSampler s) {
    uint groupSeed = psHash(s.pixelSeed + s.group * 0x9E3779B9u);
    s.group += 1u;
    uint index = psOwenScramble(s.pass, psHash(groupSeed ^ 0x5851F42Du));
    uvec2 p = psSobol2D(index);
    return uvec2(psOwenScramble(p.x, psHash(groupSeed ^ 0x68E31DA4u)),
                 psOwenScramble(p.y, psHash(groupSeed ^ 0xB5297A4Du)));
}

// 24 bits, never rounded up to 1 (util::unitFloat).
float psUnit(uint bits) { return float(bits >> 8) * (1.0 / 16777216.0); }
float psNext1D(inout PathSampler s) { return psUnit(psNextPoint(s).x); }
vec2 psNext2D(inout PathSampler s) {
    uvec2 p = psNextPoint(s);
    return vec2(psUnit(p.x), psUnit(p.y));
}

#endif
