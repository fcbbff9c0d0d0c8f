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

constexpr uint32_t reverseBits(uint32_t x) {
    x = ((x >> 1) & 0x55555555U) | ((x & 0x55555555U) << 1);
    x = ((x >> 2) & 0x33333333U) | ((x & 0x33333333U) << 2);
    x = ((x >> 4) & 0x0F0F0F0FU) | ((x & 0x0F0F0F0FU) << 4);
    x = ((x >> 8) & 0x00FF00FFU) | ((x & 0x00FF00FFU) << 8);
    return (x >> 16) | (x << 16);
}

// Nested uniform (Owen) scramble of the bits of x, most significant first: a hash that only
// lets each bit depend on the bits above it (Laine-Karras on reversed bits; Vegdahl's constants).
constexpr uint32_t owenScramble(uint32_t x, uint32_t seed) {
    x = reverseBits(x);
    x ^= x * 0x3d20adeaU;
    x += seed;
    x *= (seed >> 16) | 1U;
    x ^= x * 0x05526c56U;
    x ^= x * 0x53a22864U;
    return reverseBits(x);
}

// The first two Sobol' dimensions: van der Corput (the index's bits reversed) and its partner
// with direction numbers v_k = v_{k-1} ^ v_{k-1} >> 1, i.e. the Pascal matrix mod 2 applied to
// the reversed index. That matrix is the Kronecker power of [[1,0],[1,1]], so five masked
// shift-xors apply it instead of a loop over the index's 32 bits.
constexpr std::pair<uint32_t, uint32_t> sobol2D(uint32_t index) {
    const uint32_t x = reverseBits(index);
    uint32_t y = x;
    y ^= (y & 0x55555555U) << 1;
    y ^= (y & 0x33333333U) << 2;
    y ^= (y & 0x0F0F0F0FU) << 4;
    y ^= (y & 0x00FF00FFU) << 8;
    y ^= (y & 0x0000FFFFU) << 16;
    return {x, y};
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
        : m_pixelSeed(hashU32(pixelIndex ^ seedKey)), m_pass(pass) {}

    float next1D() { return unitFloat(nextPoint().first); }
    std::pair<float, float> next2D() {
        const auto [x, y] = nextPoint();
        return {unitFloat(x), unitFloat(y)};
    }

private:
    std::pair<uint32_t, uint32_t> nextPoint() {
        const uint32_t groupSeed = hashU32(m_pixelSeed + m_group++ * 0x9E3779B9U);
        const uint32_t index = owenScramble(m_pass, hashU32(groupSeed ^ 0x5851F42DU));
        const auto [x, y] = sobol2D(index);
        return {owenScramble(x, hashU32(groupSeed ^ 0x68E31DA4U)),
                owenScramble(y, hashU32(groupSeed ^ 0xB5297A4DU))};
    }

    uint32_t m_pixelSeed;
    uint32_t m_pass;
    uint32_t m_group = 0;
};

} // namespace wavelit::util
