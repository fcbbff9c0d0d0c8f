#include "relight/camera_lights.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace wavelit::relight {
namespace {
constexpr double kPi = std::numbers::pi;

glm::vec3 seen(const scene::Light& light, const glm::vec3& o, const glm::vec3& d, float tMax) {
    const glm::vec3 power = light.color * light.intensity;
    switch (light.type) {
    case scene::LightType::Sphere: {
        if (!(light.radius > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 oc = o - light.position;
        const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - light.radius * light.radius;
        const float disc = b * b - c;
        if (c <= 0.0f || disc < 0.0f) return glm::vec3(0.0f); // inside, or missed
        const float t = -b - std::sqrt(disc);
        if (!(t > 0.0f) || !(t < tMax)) return glm::vec3(0.0f);
        return power * float(1.0 / (4.0 * kPi * kPi * double(light.radius) * light.radius));
    }
    case scene::LightType::Rect: {
        const float len = glm::length(light.direction), area = light.size.x * light.size.y;
        if (!(len > 0.0f) || !(area > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 n = light.direction / len;
        const float denom = glm::dot(d, n);
        if (!(denom < 0.0f)) return glm::vec3(0.0f); // the front face looks back along the ray
        const float t = glm::dot(light.position - o, n) / denom;
        if (!(t > 0.0f) || !(t < tMax)) return glm::vec3(0.0f);
        const glm::vec3 ref = std::abs(n.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        const glm::vec3 u = glm::normalize(glm::cross(ref, n)), v = glm::cross(n, u);
        const glm::vec3 q = o + t * d - light.position;
        if (std::abs(glm::dot(q, u)) > 0.5f * light.size.x || std::abs(glm::dot(q, v)) > 0.5f * light.size.y)
            return glm::vec3(0.0f);
        return power * float(1.0 / (kPi * double(area)));
    }
    case scene::LightType::Sun: {
        const double half = 0.5 * double(light.angularDiameterDeg) * kPi / 180.0;
        const float len = glm::length(light.direction);
        if (std::isfinite(tMax) || half <= 0.0 || !(len > 0.0f)) return glm::vec3(0.0f);
        if (double(glm::dot(d, -light.direction / len)) < std::cos(half)) return glm::vec3(0.0f);
        const double s = std::sin(half);
        return power * float(1.0 / (kPi * s * s));
    }
    default: return glm::vec3(0.0f); // delta lights are never hit
    }
}
} // namespace

glm::vec3 lightSeenAlongRay(const scene::Light& light, const glm::vec3& origin, const glm::vec3& dir,
                            float tMax) {
    return seen(light, origin, dir, tMax);
}

glm::vec3 lightSeenByPixel(const scene::Light& light, const scene::Camera& camera, const CameraRays& rays,
                           int x, int y, float tMax) {
    if (light.type == scene::LightType::Point || light.type == scene::LightType::Spot) return glm::vec3(0.0f);
    constexpr int kSide = 4;
    glm::vec3 sum(0.0f);
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i)
            sum += seen(light, camera.position, rays.direction(x, y, (i + 0.5f) / kSide, (j + 0.5f) / kSide), tMax);
    return sum / float(kSide * kSide);
}

} // namespace wavelit::relight
