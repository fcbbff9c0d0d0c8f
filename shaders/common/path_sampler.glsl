// The random numbers of one path: shuffled, Owen-scrambled Sobol' points per draw group, indexed
// by the pass. The same code as renderer/util/path_sampler.h (read its comment for why), so the
// GPU and CPU tracers draw the same numbers for the same (seed key, pixel, pass).
#ifndef WAVELIT_PATH_SAMPLER_GLSL
#define WAVELIT_PATH_SAMPLER_GLSL

struct PathSampler {
    uint pixelSeed;
    uint reversedPass;
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

// util::laineKarras: on reversed bits, a nested uniform (Owen) scramble.
uint psLaineKarras(uint x, uint seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

uint psOwenScramble(uint x, uint seed) {
    return bitfieldReverse(psLaineKarras(bitfieldReverse(x), seed));
}

// util::sobolPartner: the Pascal matrix mod 2 applied to the van der Corput value.
uint psSobolPartner(uint x) {
    x ^= (x & 0x55555555u) << 1;
    x ^= (x & 0x33333333u) << 2;
    x ^= (x & 0x0F0F0F0Fu) << 4;
    x ^= (x & 0x00FF00FFu) << 8;
    return x ^ ((x & 0x0000FFFFu) << 16);
}

PathSampler psStart(uint seedKey, uint pixelIndex, uint pass) {
    PathSampler s;
    s.pixelSeed = psHash(pixelIndex ^ seedKey);
    s.reversedPass = bitfieldReverse(pass);
    s.group = 0u;
    return s;
}

// The group's seed; x = the van der Corput value of the group's shuffled pass index.
uint psNextGroup(inout PathSampler s, out uint x) {
    uint groupSeed = psHash(s.pixelSeed + s.group * 0x9E3779B9u);
    s.group += 1u;
    x = psLaineKarras(s.reversedPass, psHash(groupSeed ^ 0x5851F42Du));
    return groupSeed;
}

// 24 bits, never rounded up to 1 (util::unitFloat).
float psUnit(uint bits) { return float(bits >> 8) * (1.0 / 16777216.0); }

float psNext1D(inout PathSampler s) {
    uint x;
    uint groupSeed = psNextGroup(s, x);
    return psUnit(psOwenScramble(x, psHash(groupSeed ^ 0x68E31DA4u)));
}

vec2 psNext2D(inout PathSampler s) {
    uint x;
    uint groupSeed = psNextGroup(s, x);
    return vec2(psUnit(psOwenScramble(x, psHash(groupSeed ^ 0x68E31DA4u))),
                psUnit(psOwenScramble(psSobolPartner(x), psHash(groupSeed ^ 0xB5297A4Du))));
}

#endif
