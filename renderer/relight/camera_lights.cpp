#include "relight/camera_lights.h"

#include <glm/geometric.hpp>

#include <algorithm>
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
    // Most pixels are nowhere near the light: one cone test against the light's bounding cone
    // widened by the pixel's own (centre to corner) skips the 16 sub-pixel rays (a light edit
    // runs this for every pixel).
    const glm::vec3 centre = rays.direction(x, y), corner = rays.direction(x, y, 0.0f, 0.0f);
    const double pixel = std::acos(std::clamp(double(glm::dot(centre, corner)), -1.0, 1.0));
    glm::vec3 axis(0.0f);
    double cone = kPi; // half angle of a cone about axis that holds the light as seen from the eye
    if (light.type == scene::LightType::Sun) {
        const float len = glm::length(light.direction);
        if (len > 0.0f) {
            axis = -light.direction / len;
            cone = 0.5 * double(light.angularDiameterDeg) * kPi / 180.0;
        }
    } else {
        const float r = light.type == scene::LightType::Sphere ? light.radius : 0.5f * glm::length(light.size);
        const glm::vec3 toLight = light.position - camera.position;
        const float d = glm::length(toLight);
        if (d > r && d > 0.0f) {
            axis = toLight / d;
            cone = std::asin(std::min(1.0, double(r) / double(d)));
        }
    }
    if (cone + 2.0 * pixel + 1e-3 < kPi &&
        double(glm::dot(centre, axis)) < std::cos(cone + 2.0 * pixel + 1e-3))
        return glm::vec3(0.0f);
    constexpr int kSide = 4;
    glm::vec3 sum(0.0f);
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i)
            sum += seen(light, camera.position, rays.direction(x, y, (i + 0.5f) / kSide, (j + 0.5f) / kSide), tMax);
    return sum / float(kSide * kSide);
}

} // namespace wavelit::relight
