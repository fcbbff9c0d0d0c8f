#include "relight/texel_directions.h"

#include "wavelet/sphere_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

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
    m_texelSolidAngle = 4.0 * std::numbers::pi / double(m_dirs.size());
    m_texelRadius = widest * 1.01 + 1e-6;
}

uint32_t TexelDirections::texelOf(const glm::vec3& direction) const {
    return texelOfUnit(glm::normalize(direction));
}

bool anyBit(const TexelBits& b) {
    return std::any_of(b.begin(), b.end(), [](uint64_t w) { return w != 0; });
}

} // namespace wavelit::relight
