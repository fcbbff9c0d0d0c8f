// The directions of a 2^n x 2^n equal-area octahedral map (architecture.md §3), the one sphere
// grid every relighting factor lives on: texel t = y * side + x has centre direction dirs[t] and
// solid angle 4 pi / side^2. Texel-centre values are what the factors hold (Haar functions are
// piecewise constant per texel), so <T, F> over the sphere is 4 pi times the unit-square inner
// product of the Haar coefficients.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
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
    // kSub x kSub stratified directions inside texel t (for averaging a narrow BRDF lobe over it),
    // as their x, y and z components, kSub^2 floats each (what a vectorised frame change reads:
    // relight/texel_values.cpp).
    static constexpr int kSub = 4;
    const float* subX(size_t texel) const { return &m_subX[texel * kSub * kSub]; }
    const float* subY(size_t texel) const { return &m_subY[texel * kSub * kSub]; }
    const float* subZ(size_t texel) const { return &m_subZ[texel * kSub * kSub]; }
    // The same at kCoarseSub x kCoarseSub: a material edit's approximate first answer for a
    // narrow lobe (a quarter of the BRDF evaluations; docs/relighting.md §7.0h).
    static constexpr int kCoarseSub = 2;
    const float* coarseSubX(size_t texel) const {
        return &m_coarseX[texel * kCoarseSub * kCoarseSub];
    }
    const float* coarseSubY(size_t texel) const {
        return &m_coarseY[texel * kCoarseSub * kCoarseSub];
    }
    const float* coarseSubZ(size_t texel) const {
        return &m_coarseZ[texel * kCoarseSub * kCoarseSub];
    }
    // Bit t set where direction(t) . a > 0 and direction(t) . b > 0 (TexelBits words; the same
    // float products and sums as glm::dot): a point's horizon, computed for every point the
    // preview builds or a drag carries, one word at a time from the directions' components.
    std::vector<uint64_t> aboveBoth(const glm::vec3& a, const glm::vec3& b) const;
    // direction(t)'s components as arrays (padded with zeros to whole 64-texel words).
    const float* xs() const { return m_x.data(); }
    const float* ys() const { return m_y.data(); }
    const float* zs() const { return m_z.data(); }
    size_t paddedCount() const { return m_x.size(); }
    // The texel holding direction d (any non-zero vector).
    uint32_t texelOf(const glm::vec3& d) const;
    // The same for a unit vector, inline: a rect light's drag maps ~30 samples per point through
    // it, and the call and the second normalisation were a quarter of its cost.
    uint32_t texelOfUnit(const glm::vec3& unit) const;

private:
    int m_level;
    std::vector<glm::vec3> m_dirs;
    std::vector<float> m_subX, m_subY, m_subZ, m_coarseX, m_coarseY, m_coarseZ;
    std::vector<float> m_x, m_y, m_z; // m_dirs' components, padded with zeros to whole words
    double m_texelSolidAngle;
    double m_texelRadius;
};

// OctahedralMap::toSquare (pbrt-v4's EqualAreaSphereToSquare) in float with pbrt's polynomial
// arctangent (|error| < 1e-5 rad): the light projection maps every light sample through it, and
// the double-precision map's atan was most of a light edit's time. A direction within 1e-5 of a
// texel edge may land in the neighbouring texel, which moves no energy between lights and points.
inline uint32_t TexelDirections::texelOfUnit(const glm::vec3& d) const {
    const float dx = d.x, dy = d.z, dz = d.y; // the map's axes
    const float x = std::abs(dx), y = std::abs(dy), z = std::abs(dz);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z));
    const float a = std::max(x, y);
    const float b = a == 0.0f ? 0.0f : std::min(x, y) / a;
    // atan(b) * 2/pi on [0, 1] (pbrt-v4).
    constexpr float t1 = 0.406758566246788489601959989e-5f, t2 = 0.636226545274016134946890922156f,
                    t3 = 0.61572017898280213493197203466e-2f, t4 = -0.247333733281268944196501420480f,
                    t5 = 0.881770664775316294736387951347e-1f, t6 = 0.419038818029165735901852432784e-1f,
                    t7 = -0.251390972343483509333252996350e-1f;
    float phi = t1 + b * (t2 + b * (t3 + b * (t4 + b * (t5 + b * (t6 + b * t7)))));
    phi = x < y ? 1.0f - phi : phi; // selects, not branches: the light samples' order is random
    const float v0 = phi * r, u0 = r - v0;
    const bool lower = dz < 0.0f;
    const float u = lower ? 1.0f - v0 : u0, v = lower ? 1.0f - u0 : v0;
    const int n = side();
    const int px = std::clamp(int(0.5f * (std::copysign(u, dx) + 1.0f) * float(n)), 0, n - 1);
    const int py = std::clamp(int(0.5f * (std::copysign(v, dy) + 1.0f) * float(n)), 0, n - 1);
    return uint32_t(py * n + px);
}

// One bit per texel (1: set). Words of 64 texels.
using TexelBits = std::vector<uint64_t>;
inline TexelBits makeBits(size_t texels) { return TexelBits((texels + 63) / 64, 0); }
inline bool testBit(const TexelBits& b, size_t t) { return (b[t >> 6] >> (t & 63)) & 1u; }
inline void setBit(TexelBits& b, size_t t) { b[t >> 6] |= uint64_t(1) << (t & 63); }
bool anyBit(const TexelBits& b);

} // namespace wavelit::relight
