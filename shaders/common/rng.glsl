// PCG32 (O'Neill 2014), the same step as renderer/util/rng.h so the GPU and CPU tracers draw the
// same numbers for the same (seed, stream). Needs 64-bit integers (shaderInt64; lavapipe has it).
#ifndef WAVELIT_RNG_GLSL
#define WAVELIT_RNG_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

struct Pcg32 {
    uint64_t state;
    uint64_t inc;
};

uint pcgNext(inout Pcg32 r) {
    uint64_t old = r.state;
    r.state = old * 6364136223846793005UL + r.inc;
    uint xorshifted = uint(((old >> 18) ^ old) >> 27);
    uint rot = uint(old >> 59);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
}

Pcg32 pcgSeed(uint64_t seed, uint64_t stream) {
    Pcg32 r;
    r.state = 0UL;
    r.inc = (stream << 1) | 1UL;
    pcgNext(r);
    r.state += seed;
    pcgNext(r);
    return r;
}

// Uniform in [0, 1): 24 random mantissa bits, never rounded up to 1 (util::Pcg32::nextFloat).
float pcgFloat(inout Pcg32 r) { return float(pcgNext(r) >> 8) * (1.0 / 16777216.0); }

#endif
