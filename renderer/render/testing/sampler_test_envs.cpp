#include "render/testing/sampler_test_envs.h"

#include "scene/image_io.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace wavelit::render {
namespace {
constexpr double kPi = std::numbers::pi;

glm::dvec3 texelCentre(int x, int y, int w, int h) {
    const double phi = (x + 0.5) / w * 2.0 * kPi - kPi, theta = (y + 0.5) / h * kPi;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}
} // namespace

scene::Environment makeSunSkyEnvironment(int width, const glm::vec3& sunDirection, double ratio,
                                         double angularDiameterDeg) {
    const int w = width, h = width / 2;
    auto image = std::make_shared<util::ImageRGB>(w, h);
    double sum = 0.0, weight = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::dvec3 d = texelCentre(x, y, w, h);
            const glm::vec3 c = d.y > 0.0
                                    ? glm::vec3(0.35f, 0.5f, 0.9f) * float(0.4 + 0.6 * d.y) +
                                          glm::vec3(0.2f) * float(0.5 + 0.5 * d.x)
                                    : glm::vec3(0.12f, 0.1f, 0.08f);
            image->at(x, y) = c;
            const double dw = std::sin((y + 0.5) / h * kPi);
            sum += double(util::luminance(c)) * dw;
            weight += dw;
        }
    const double skyMean = sum / weight;
    const glm::dvec3 sun = glm::normalize(glm::dvec3(sunDirection));
    const double radius = 0.5 * angularDiameterDeg * kPi / 180.0;
    const glm::vec3 sunRadiance(float(ratio * skyMean));
    bool painted = false;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (std::acos(std::clamp(glm::dot(texelCentre(x, y, w, h), sun), -1.0, 1.0)) < radius) {
                image->at(x, y) = sunRadiance;
                painted = true;
            }
    if (!painted) {
        const double u = 0.5 + std::atan2(sun.z, sun.x) / (2.0 * kPi);
        const double v = std::acos(std::clamp(sun.y, -1.0, 1.0)) / kPi;
        image->at(std::min(int(u * w), w - 1), std::min(int(v * h), h - 1)) = sunRadiance;
    }
    scene::Environment env;
    env.path = "synthetic-sun-sky";
    env.image = image;
    return env;
}

util::Result<scene::Environment> loadDownsampledEnvironment(const std::string& path,
                                                            int maxWidth) {
    auto loaded = scene::loadImage(path);
    if (!loaded)
        return loaded.error();
    util::ImageRGB img = std::move(loaded->image);
    while (img.width > maxWidth && img.width % 2 == 0 && img.height % 2 == 0) {
        util::ImageRGB half(img.width / 2, img.height / 2);
        for (int y = 0; y < half.height; ++y)
            for (int x = 0; x < half.width; ++x)
                half.at(x, y) = 0.25f * (img.at(2 * x, 2 * y) + img.at(2 * x + 1, 2 * y) +
                                         img.at(2 * x, 2 * y + 1) + img.at(2 * x + 1, 2 * y + 1));
        img = std::move(half);
    }
    scene::Environment env;
    env.path = path;
    env.image = std::make_shared<util::ImageRGB>(std::move(img));
    return env;
}

} // namespace wavelit::render
