// The directions of a 2^n x 2^n equal-area octahedral map (architecture.md §3), the one sphere
// grid every relighting factor lives on: texel t = y * side + x has centre direction dirs[t] and
// solid angle 4 pi / side^2. Texel-centre values are what the factors hold (Haar functions are
// piecewise constant per texel), so <T, F> over the sphere is 4 pi times the unit-square inner
// product of the Haar coefficients.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wavelit::relight {

class TexelDirections {
public:
    explicit TexelDirections(int level);

    int level() const { return m_level; }
    int side() const { return 1 << m_level; }
    size_t count() const { return m_dirs.size(); }
    const glm::vec3& direction(size_t texel) const { return m_dirs[texel]; }
    double texelSolidAngle() const { return m_texelSolidAngle; }
    // Half the largest angle between a texel's centre and its corners (radians), padded: a cone
    // test against centre directions widened by it never misses a texel the cone touches.
    double texelRadius() const { return m_texelRadius; }
    // kSub x kSub stratified directions inside texel t (for averaging a narrow BRDF lobe over it).
    static constexpr int kSub = 4;
    const glm::vec3* subDirections(size_t texel) const { return &m_sub[texel * kSub * kSub]; }
    // The texel holding direction d (any non-zero vector).
    uint32_t texelOf(const glm::vec3& d) const;

private:
    int m_level;
    std::vector<glm::vec3> m_dirs;
    std::vector<glm::vec3> m_sub;
    double m_texelSolidAngle;
    double m_texelRadius;
};

// One bit per texel (1: set). Words of 64 texels.
using TexelBits = std::vector<uint64_t>;
inline TexelBits makeBits(size_t texels) { return TexelBits((texels + 63) / 64, 0); }
inline bool testBit(const TexelBits& b, size_t t) { return (b[t >> 6] >> (t & 63)) & 1u; }
inline void setBit(TexelBits& b, size_t t) { b[t >> 6] |= uint64_t(1) << (t & 63); }
bool anyBit(const TexelBits& b);

} // namespace wavelit::relight
