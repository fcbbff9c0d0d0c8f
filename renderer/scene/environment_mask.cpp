#include "scene/environment_mask.h"

#include "scene/scene.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace wavelit::scene {
namespace {
constexpr double kPi = 3.14159265358979323846;
} // namespace

glm::dvec3 equirectTexelDirection(int width, int height, int x, int y) {
    const double phi = ((double(x) + 0.5) / double(width) - 0.5) * 2.0 * kPi;
    const double theta = (double(y) + 0.5) / double(height) * kPi;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

double equirectTexelSolidAngle(int width, int height, int y) {
    const double theta0 = double(y) / double(height) * kPi, theta1 = double(y + 1) / double(height) * kPi;
    return 2.0 * kPi / double(width) * (std::cos(theta0) - std::cos(theta1));
}

bool hasEnvironmentMask(const Environment& env) { return env.maskRadiusDeg > 0.0f; }

bool environmentMaskHides(const Environment& env, int width, int height, int x, int y) {
    if (!hasEnvironmentMask(env)) return false;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(env.maskDirection));
    const double cosRadius = std::cos(double(env.maskRadiusDeg) * kPi / 180.0);
    return glm::dot(equirectTexelDirection(width, height, x, y), axis) >= cosRadius;
}

util::ImageRGB applyEnvironmentMask(const util::ImageRGB& map, const Environment& env) {
    util::ImageRGB out = map;
    if (!hasEnvironmentMask(env)) return out;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            if (environmentMaskHides(env, map.width, map.height, x, y)) out.at(x, y) = glm::vec3(0.0f);
    return out;
}

} // namespace wavelit::scene
