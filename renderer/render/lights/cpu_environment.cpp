#include "render/lights/cpu_environment.h"

#include <algorithm>
#include <cmath>

namespace wavelit::render {
namespace {
constexpr float kPi = 3.14159265358979323846f;
} // namespace

CpuEnvironment::CpuEnvironment(const scene::Environment& env)
    : m_image(env.image && !env.image->empty() ? env.image : nullptr),
      m_scale(env.intensity * env.tint) {
    float yaw = env.rotationDeg * (kPi / 180.0f);
    m_cosYaw = std::cos(yaw);
    m_sinYaw = std::sin(yaw);
}

glm::vec2 CpuEnvironment::equirect(const glm::vec3& dir) const {
    // Rotation by −yaw about +Y: R_y(θ) maps (x, z) to (x cosθ + z sinθ, −x sinθ + z cosθ).
    float x = m_cosYaw * dir.x - m_sinYaw * dir.z;
    float z = m_sinYaw * dir.x + m_cosYaw * dir.z;
    float u = 0.5f + std::atan2(z, x) / (2.0f * kPi);
    float v = std::acos(std::clamp(dir.y, -1.0f, 1.0f)) / kPi;
    return glm::vec2(u, v);
}

glm::vec3 CpuEnvironment::radianceAt(const glm::vec2& uv) const {
    if (!m_image) return m_scale;
    const int w = m_image->width, h = m_image->height;
    // uv ≥ 0 always (atan2 ∈ [−π, π], acos ∈ [0, π]), so int() truncation is a floor; the
    // `> 0` tests also send a NaN direction to texel 0 instead of an undefined conversion.
    const float fx = uv.x * float(w), fy = uv.y * float(h);
    const int x = fx > 0.0f ? std::min(int(fx), w - 1) : 0;
    const int y = fy > 0.0f ? std::min(int(fy), h - 1) : 0;
    return m_image->at(x, y) * m_scale;
}

} // namespace wavelit::render
