#include "render/lights/light_spherical_rect.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::render {
namespace {
constexpr float kTwoPi = 6.28318530717958647692f;
// hv² this close to 1 puts the sample on the far edge (the paper's guard against 0/0).
constexpr float kEdgeGuard = 1e-6f;
} // namespace

SphericalRect::SphericalRect(const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey,
                             const glm::vec3& o)
    : m_o(o) {
    const float exl = glm::length(ex), eyl = glm::length(ey);
    m_x = ex / exl;
    m_y = ey / eyl;
    m_z = glm::cross(m_x, m_y);
    const glm::vec3 d = corner - o;
    m_z0 = glm::dot(d, m_z);
    if (m_z0 > 0.0f) { // the local frame has the rectangle at z0 < 0
        m_z = -m_z;
        m_z0 = -m_z0;
    }
    m_x0 = glm::dot(d, m_x);
    m_y0 = glm::dot(d, m_y);
    m_x1 = m_x0 + exl;
    m_y1 = m_y0 + eyl;
    const glm::vec3 v00(m_x0, m_y0, m_z0), v01(m_x0, m_y1, m_z0), v10(m_x1, m_y0, m_z0),
        v11(m_x1, m_y1, m_z0);
    const glm::vec3 n0 = glm::normalize(glm::cross(v00, v10));
    const glm::vec3 n1 = glm::normalize(glm::cross(v10, v11));
    const glm::vec3 n2 = glm::normalize(glm::cross(v11, v01));
    const glm::vec3 n3 = glm::normalize(glm::cross(v01, v00));
    auto angle = [](const glm::vec3& a, const glm::vec3& b) {
        return std::acos(std::clamp(-glm::dot(a, b), -1.0f, 1.0f));
    };
    const float g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    m_b0 = n0.z;
    m_b1 = n2.z;
    m_k = kTwoPi - g2 - g3;
    m_solidAngle = g0 + g1 - m_k;
}

glm::vec3 SphericalRect::samplePoint(glm::vec2 u) const {
    // 1. x from the area of the sub-rectangle left of it (paper eq. 6–8).
    const float au = u.x * m_solidAngle + m_k;
    const float fu = (std::cos(au) * m_b0 - m_b1) / std::sin(au);
    float cu = std::copysign(1.0f, fu) / std::sqrt(fu * fu + m_b0 * m_b0);
    cu = std::clamp(cu, -1.0f, 1.0f);
    const float xu = std::clamp(-(cu * m_z0) / std::sqrt(std::max(0.0f, 1.0f - cu * cu)), m_x0,
                                m_x1);
    // 2. y uniform in the projected height along that line (eq. 10–11).
    const float d = std::sqrt(xu * xu + m_z0 * m_z0);
    const float h0 = m_y0 / std::sqrt(d * d + m_y0 * m_y0);
    const float h1 = m_y1 / std::sqrt(d * d + m_y1 * m_y1);
    const float hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
    const float yv = hv2 < 1.0f - kEdgeGuard ? hv * d / std::sqrt(1.0f - hv2) : m_y1;
    return m_o + xu * m_x + yv * m_y + m_z0 * m_z;
}

} // namespace wavelit::render
