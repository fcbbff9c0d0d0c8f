#include "viewport/view_projection.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace wavelit::editor {

ViewProjection::ViewProjection(const scene::Camera& camera, int imageWidth, int imageHeight)
    : m_position(camera.position), m_width(imageWidth > 0 ? imageWidth : 1),
      m_height(imageHeight > 0 ? imageHeight : 1) {
    m_forward = glm::normalize(camera.target - camera.position);
    m_right = glm::normalize(glm::cross(m_forward, camera.up));
    m_up = glm::cross(m_right, m_forward);
    m_tanHalf = std::tan(0.5f * glm::radians(camera.verticalFovDeg));
    m_aspect = float(m_width) / float(m_height);
}

ViewRay ViewProjection::ray(glm::vec2 pixel) const {
    const float sx = (2.0f * pixel.x / float(m_width) - 1.0f) * m_tanHalf * m_aspect;
    const float sy = (1.0f - 2.0f * pixel.y / float(m_height)) * m_tanHalf;
    return {m_position, glm::normalize(m_forward + sx * m_right + sy * m_up)};
}

float ViewProjection::depth(const glm::vec3& world) const {
    return glm::dot(world - m_position, m_forward);
}

std::optional<glm::vec2> ViewProjection::project(const glm::vec3& world) const {
    const glm::vec3 d = world - m_position;
    const float z = glm::dot(d, m_forward);
    if (!(z > 1e-6f)) return std::nullopt;
    const float sx = glm::dot(d, m_right) / (z * m_tanHalf * m_aspect);
    const float sy = glm::dot(d, m_up) / (z * m_tanHalf);
    return glm::vec2((sx + 1.0f) * 0.5f * float(m_width), (1.0f - sy) * 0.5f * float(m_height));
}

float ViewProjection::worldPerPixel(float depth) const {
    return 2.0f * depth * m_tanHalf / float(m_height);
}

std::optional<glm::vec3> intersectPlane(const ViewRay& ray, const glm::vec3& point, const glm::vec3& normal) {
    const float denom = glm::dot(ray.direction, normal);
    if (std::abs(denom) < 1e-6f) return std::nullopt;
    const float t = glm::dot(point - ray.origin, normal) / denom;
    if (!(t > 0.0f)) return std::nullopt;
    return ray.origin + t * ray.direction;
}

} // namespace wavelit::editor
