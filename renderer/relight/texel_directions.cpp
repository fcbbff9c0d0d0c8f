#include "relight/texel_directions.h"

#include "wavelet/sphere_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace wavelit::relight {
namespace {

// sub x sub stratified directions inside every texel of an n x n map, as components.
void subDirections(const wavelet::OctahedralMap& map, int n, int sub, std::vector<float>& xs,
                   std::vector<float>& ys, std::vector<float>& zs) {
    xs.resize(size_t(n) * size_t(n) * size_t(sub * sub));
    ys.resize(xs.size());
    zs.resize(xs.size());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const size_t first = (size_t(y) * size_t(n) + size_t(x)) * size_t(sub * sub);
            for (int j = 0; j < sub; ++j)
                for (int i = 0; i < sub; ++i) {
                    const glm::vec3 d(map.toDirection(
                        0, {(x + (i + 0.5) / sub) / n, (y + (j + 0.5) / sub) / n}));
                    const size_t at = first + size_t(j * sub + i);
                    xs[at] = d.x;
                    ys[at] = d.y;
                    zs[at] = d.z;
                }
        }
}

} // namespace

TexelDirections::TexelDirections(int level) : m_level(level) {
    const wavelet::OctahedralMap map;
    const int n = side();
    m_dirs.resize(size_t(n) * size_t(n));
    subDirections(map, n, kSub, m_subX, m_subY, m_subZ);
    subDirections(map, n, kCoarseSub, m_coarseX, m_coarseY, m_coarseZ);
    double widest = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::dvec3 c = map.toDirection(0, {(x + 0.5) / n, (y + 0.5) / n});
            m_dirs[size_t(y) * size_t(n) + size_t(x)] = glm::vec3(c);
            for (int corner = 0; corner < 4; ++corner) {
                const glm::dvec3 k =
                    map.toDirection(0, {double(x + (corner & 1)) / n, double(y + (corner >> 1)) / n});
                widest = std::max(widest, std::acos(std::clamp(glm::dot(c, k), -1.0, 1.0)));
            }
        }
    const size_t padded = (m_dirs.size() + 63) / 64 * 64;
    m_x.assign(padded, 0.0f);
    m_y.assign(padded, 0.0f);
    m_z.assign(padded, 0.0f);
    for (size_t t = 0; t < m_dirs.size(); ++t) {
        m_x[t] = m_dirs[t].x;
        m_y[t] = m_dirs[t].y;
        m_z[t] = m_dirs[t].z;
    }
    m_texelSolidAngle = 4.0 * std::numbers::pi / double(m_dirs.size());
    m_texelRadius = widest * 1.01 + 1e-6;
}

std::vector<uint64_t> TexelDirections::aboveBoth(const glm::vec3& a, const glm::vec3& b) const {
    std::vector<uint64_t> out(m_x.size() / 64, 0);
    for (size_t w = 0; w < out.size(); ++w) {
        const float* x = &m_x[w * 64];
        const float* y = &m_y[w * 64];
        const float* z = &m_z[w * 64];
        uint64_t word = 0;
#if defined(__SSE2__)
        // Four texels a step (the same products and sums in the same order: no FMA on SSE2),
        // their two signs as four bits.
        const __m128 ax = _mm_set1_ps(a.x), ay = _mm_set1_ps(a.y), az = _mm_set1_ps(a.z);
        const __m128 bx = _mm_set1_ps(b.x), by = _mm_set1_ps(b.y), bz = _mm_set1_ps(b.z);
        const __m128 zero = _mm_setzero_ps();
        for (int k = 0; k < 64; k += 4) {
            const __m128 vx = _mm_loadu_ps(x + k), vy = _mm_loadu_ps(y + k), vz = _mm_loadu_ps(z + k);
            const __m128 da = _mm_add_ps(_mm_add_ps(_mm_mul_ps(vx, ax), _mm_mul_ps(vy, ay)), _mm_mul_ps(vz, az));
            const __m128 db = _mm_add_ps(_mm_add_ps(_mm_mul_ps(vx, bx), _mm_mul_ps(vy, by)), _mm_mul_ps(vz, bz));
            const int bits = _mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(da, zero), _mm_cmpgt_ps(db, zero)));
            word |= uint64_t(unsigned(bits)) << k;
        }
#else
        for (int k = 0; k < 64; ++k) { // a padding direction (0, 0, 0) is above nothing
            const bool above = (x[k] * a.x + y[k] * a.y + z[k] * a.z > 0.0f) & (x[k] * b.x + y[k] * b.y + z[k] * b.z > 0.0f);
            word |= uint64_t(above) << k;
        }
#endif
        out[w] = word;
    }
    return out;
}

uint32_t TexelDirections::texelOf(const glm::vec3& direction) const {
    return texelOfUnit(glm::normalize(direction));
}

bool anyBit(const TexelBits& b) {
    return std::any_of(b.begin(), b.end(), [](uint64_t w) { return w != 0; });
}

} // namespace wavelit::relight
