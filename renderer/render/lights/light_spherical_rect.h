// Uniform sampling of the solid angle a rectangle subtends from a point (Ureña, Fajardo, King
// 2013, "An Area-Preserving Parametrization for Spherical Rectangles", §3–4): every direction
// toward the rectangle has pdf 1/S, S the solid angle, so a rect light's NEE noise is only the
// BRDF's and the cosine's — no 1/d² or 1/cos_light spikes when the point is close or grazing.
//
// Precision: S = g0 + g1 + g2 + g3 − 2π cancels when S is small (the four angles approach π/2);
// in float its absolute error is ~4e-7, so callers fall back to area sampling below
// kMinSphericalRectSolidAngle (1e-2 sr: relative error ≤ 4e-5), where d²/cos is nearly constant
// over the rectangle anyway. The GPU twin computes the same in float.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace wavelit::render {

inline constexpr float kMinSphericalRectSolidAngle = 1e-2f;

class SphericalRect {
public:
    // Rectangle corner + [0,1]² · (ex, ey) with ex ⟂ ey, seen from o (not in its plane).
    SphericalRect(const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey,
                  const glm::vec3& o);

    float solidAngle() const { return m_solidAngle; }
    // The point on the rectangle whose direction from o is uniform in solid angle, u in [0,1)².
    glm::vec3 samplePoint(glm::vec2 u) const;

private:
    glm::vec3 m_o, m_x, m_y, m_z;
    float m_z0, m_x0, m_y0, m_x1, m_y1;
    float m_b0, m_b1, m_k, m_solidAngle;
};

} // namespace wavelit::render
