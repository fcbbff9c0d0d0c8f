#include "render/reference/cpu_camera.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace wavelit::render {

CpuCamera::CpuCamera(const scene::Camera& camera, int width, int height)
    : m_origin(camera.position), m_width(width), m_height(height) {
    m_forward = glm::normalize(camera.target - camera.position);
    m_right = glm::normalize(glm::cross(m_forward, camera.up));
    m_up = glm::cross(m_right, m_forward);
    m_tanHalf = std::tan(0.5f * camera.verticalFovDeg * 3.14159265358979323846f / 180.0f);
    m_aspect = float(width) / float(height);
}

glm::vec3 CpuCamera::direction(int x, int y, float u, float v) const {
    float sx = (2.0f * (float(x) + u) / float(m_width) - 1.0f) * m_tanHalf * m_aspect;
    float sy = (1.0f - 2.0f * (float(y) + v) / float(m_height)) * m_tanHalf;
    return glm::normalize(m_forward + sx * m_right + sy * m_up);
}

} // namespace wavelit::render
