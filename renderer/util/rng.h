// PCG32 (O'Neill 2014): small, fast, reproducible across C++ and GLSL (shaders/common/rng.glsl
// implements the same step so CPU and GPU tracers can share random-number streams).
#pragma once

#include <cstdint>

namespace wavelit::util {

class Pcg32 {
public:
    static constexpr uint64_t kMultiplier = 6364136223846793005ULL;
    static constexpr uint64_t kDefaultStream = 1442695040888963407ULL;

    explicit Pcg32(uint64_t seed = 0x853c49e6748fea9bULL, uint64_t stream = 0xda3e39cb94b95bdbULL) {
        seedWith(seed, stream);
    }

    void seedWith(uint64_t seed, uint64_t stream) {
        m_state = 0;
        m_inc = (stream << 1u) | 1u;
        nextUint();
        m_state += seed;
        nextUint();
    }

    uint32_t nextUint() {
        uint64_t old = m_state;
        m_state = old * kMultiplier + m_inc;
        uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
    }

    // Uniform in [0, 1): 24 random mantissa bits so the result is never rounded up to 1.
    float nextFloat() { return static_cast<float>(nextUint() >> 8) * 0x1p-24f; }
    // Uniform in [0, 1) with 53 bits.
    double nextDouble() {
        uint64_t hi = nextUint(), lo = nextUint();
        return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1p-53;
    }

private:
    uint64_t m_state = 0;
    uint64_t m_inc = 1;
};

} // namespace wavelit::util
