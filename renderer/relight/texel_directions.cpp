#include "relight/texel_directions.h"

#include "wavelet/sphere_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::relight {

TexelDirections::TexelDirections(int level) : m_level(level) {
    const wavelet::OctahedralMap map;
    const int n = side();
    m_dirs.resize(size_t(n) * size_t(n));
    m_sub.resize(m_dirs.size() * kSub * kSub);
    double widest = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::dvec3 c = map.toDirection(0, {(x + 0.5) / n, (y + 0.5) / n});
            m_dirs[size_t(y) * size_t(n) + size_t(x)] = glm::vec3(c);
            glm::vec3* sub = &m_sub[(size_t(y) * size_t(n) + size_t(x)) * kSub * kSub];
            for (int j = 0; j < kSub; ++j)
                for (int i = 0; i < kSub; ++i)
                    sub[j * kSub + i] = glm::vec3(map.toDirection(
                        0, {(x + (i + 0.5) / kSub) / n, (y + (j + 0.5) / kSub) / n}));
            for (int corner = 0; corner < 4; ++corner) {
                const glm::dvec3 k =
                    map.toDirection(0, {double(x + (corner & 1)) / n, double(y + (corner >> 1)) / n});
                widest = std::max(widest, std::acos(std::clamp(glm::dot(c, k), -1.0, 1.0)));
            }
        }
    m_texelSolidAngle = 4.0 * std::numbers::pi / double(m_dirs.size());
    m_texelRadius = widest * 1.01 + 1e-6;
}

// OctahedralMap::toSquare (pbrt-v4's EqualAreaSphereToSquare) in float with pbrt's polynomial
// arctangent (|error| < 1e-5 rad): the light projection maps every light sample through it, and
// the double-precision map's atan was most of a light edit's time. A direction within 1e-5 of a
// texel edge may land in the neighbouring texel, which moves no energy between lights and points.
uint32_t TexelDirections::texelOf(const glm::vec3& direction) const {
    const glm::vec3 d = glm::normalize(direction);
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
    if (x < y) phi = 1.0f - phi;
    float v = phi * r, u = r - v;
    if (dz < 0.0f) {
        std::swap(u, v);
        u = 1.0f - u;
        v = 1.0f - v;
    }
    u = std::copysign(u, dx);
    v = std::copysign(v, dy);
    const int n = side();
    const int px = std::clamp(int(0.5f * (u + 1.0f) * float(n)), 0, n - 1);
    const int py = std::clamp(int(0.5f * (v + 1.0f) * float(n)), 0, n - 1);
    return uint32_t(py * n + px);
}

bool anyBit(const TexelBits& b) {
    return std::any_of(b.begin(), b.end(), [](uint64_t w) { return w != 0; });
}

} // namespace wavelit::relight
