// The random numbers of one path: a shuffled, Owen-scrambled Sobol' (0,2)-sequence per draw
// (Burley 2020, "Practical Hash-based Owen Scrambling"), indexed by the pass.
//
// Why: with independent random numbers (PCG) the N passes of a pixel choose, say, the sun or the
// sky in env NEE by N coin flips; the count of sun draws varies from pixel to pixel and that
// binomial noise dominates a sun-lit diffuse image. The passes of one pixel here form a
// stratified point set in every 2D draw (pixel jitter, light sample, env sample, continuation):
// any 2^k consecutive passes from pass 0 put one point in each of 2^k elementary intervals.
// Each point alone is uniform in [0,1)^2 (Owen scrambling), so every estimator stays unbiased.
//
// Draws are grouped: each call of next1D/next2D takes the next group, which has its own
// scramble seed and its own shuffle of the pass index (padding): draws of different groups are
// decorrelated, so stratification never couples, e.g., the jitter with the light sample.
// shaders/common/path_sampler.glsl is the same code, so the CPU and GPU tracers draw the same
// numbers for the same (seed, pixel, pass).
#pragma once

#include <cstdint>
#include <utility>

namespace wavelit::util {

// 32-bit integer hash (Wellons' lowbias32): full avalanche, cheap in GLSL.
constexpr uint32_t hashU32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Byte swap, then the bits within each byte.
constexpr uint32_t reverseBits(uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x >> 1) & 0x55555555U) | ((x & 0x55555555U) << 1);
    x = ((x >> 2) & 0x33333333U) | ((x & 0x33333333U) << 2);
    return ((x >> 4) & 0x0F0F0F0FU) | ((x & 0x0F0F0F0FU) << 4);
}

// The Laine-Karras permutation with Vegdahl's constants: each output bit depends only on the
// input bits below it (carries run upward), so on reversed bits it is a nested uniform scramble.
constexpr uint32_t laineKarras(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeaU;
    x += seed;
    x *= (seed >> 16) | 1U;
    x ^= x * 0x05526c56U;
    x ^= x * 0x53a22864U;
    return x;
}

// Nested uniform (Owen) scramble of the bits of x, most significant first: each bit depends
// only on the bits above it.
constexpr uint32_t owenScramble(uint32_t x, uint32_t seed) {
    return reverseBits(laineKarras(reverseBits(x), seed));
}

// The Sobol' partner of van der Corput (direction numbers v_k = v_{k-1} ^ v_{k-1} >> 1) from the
// van der Corput value x (the index's bits reversed): the Pascal matrix mod 2 applied to x. That
// matrix is the Kronecker power of [[1,0],[1,1]], so five masked shift-xors apply it instead of
// a loop over the index's 32 bits.
constexpr uint32_t sobolPartner(uint32_t x) {
    x ^= (x & 0x55555555U) << 1;
    x ^= (x & 0x33333333U) << 2;
    x ^= (x & 0x0F0F0F0FU) << 4;
    x ^= (x & 0x00FF00FFU) << 8;
    return x ^ ((x & 0x0000FFFFU) << 16);
}

// The first two Sobol' dimensions of point `index`.
constexpr std::pair<uint32_t, uint32_t> sobol2D(uint32_t index) {
    const uint32_t x = reverseBits(index);
    return {x, sobolPartner(x)};
}

// 24 bits, so the result is never rounded up to 1.
constexpr float unitFloat(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

class PathSampler {
public:
    // The 32-bit key of a render's 64-bit seed (what the GPU tracer's push constant carries).
    static constexpr uint32_t seedKey(uint64_t seed) {
        return hashU32(uint32_t(seed) ^ hashU32(uint32_t(seed >> 32)));
    }

    PathSampler(uint32_t seedKey, uint32_t pixelIndex, uint32_t pass)
        : m_pixelSeed(hashU32(pixelIndex ^ seedKey)), m_reversedPass(reverseBits(pass)) {}

    float next1D() {
        const Group g = nextGroup();
        return unitFloat(scrambled(g.seed, 0x68E31DA4U, g.x));
    }
    std::pair<float, float> next2D() {
        const Group g = nextGroup();
        return {unitFloat(scrambled(g.seed, 0x68E31DA4U, g.x)),
                unitFloat(scrambled(g.seed, 0xB5297A4DU, sobolPartner(g.x)))};
    }

private:
    // A draw group: its seed and x, the van der Corput value of its shuffled pass index.
    struct Group {
        uint32_t seed;
        uint32_t x;
    };
    // x = owenScramble(pass) reversed, which is laineKarras on the reversed pass: no reversal.
    Group nextGroup() {
        const uint32_t seed = hashU32(m_pixelSeed + m_group++ * 0x9E3779B9U);
        return {seed, laineKarras(m_reversedPass, hashU32(seed ^ 0x5851F42DU))};
    }
    static uint32_t scrambled(uint32_t groupSeed, uint32_t salt, uint32_t coordinate) {
        return owenScramble(coordinate, hashU32(groupSeed ^ salt));
    }

    uint32_t m_pixelSeed;
    uint32_t m_reversedPass;
    uint32_t m_group = 0;
};

} // namespace wavelit::util
