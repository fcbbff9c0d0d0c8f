#include "render/lights/extract_sun.h"

#include "scene/environment_mask.h"
#include "util/path_util.h"
#include "wavelet/sun_search.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace wavelit::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string unusedLightName(const scene::Scene& scene) {
    auto taken = [&](const std::string& name) {
        return std::any_of(scene.lighting.lights.begin(), scene.lighting.lights.end(),
                           [&](const scene::Light& l) { return l.name == name; });
    };
    std::string name = "sun";
    for (int i = 2; taken(name); ++i) {
        name = "sun";
        name += std::to_string(i);
    }
    return name;
}

} // namespace

glm::dvec3 mapToWorld(const glm::dvec3& m, float rotationDeg) {
    const double yaw = double(rotationDeg) * kPi / 180.0, c = std::cos(yaw), s = std::sin(yaw);
    // The lookup maps world d to m = (c d.x - s d.z, d.y, s d.x + c d.z); this is its inverse.
    return {c * m.x + s * m.z, m.y, -s * m.x + c * m.z};
}

util::Result<ExtractedSun> extractSun(const scene::Scene& input, const std::string& sourceFile) {
    const scene::Environment& env = input.lighting.environment;
    auto fail = [&](const std::string& why) {
        std::string reason = "extract sun: ";
        reason += why;
        // Where the environment sits in that file: a setup holds it at the top, a scene under
        // its inline lighting.
        const bool setup = util::lowerExtension(sourceFile) == ".wllight";
        return util::makeError(util::ErrorKind::Invalid, sourceFile, reason,
                               setup ? "/environment" : "/lighting/environment");
    };
    if (env.path.empty() || !env.image || env.image->empty())
        return fail("the environment is a constant colour, not a map; there is no sun to extract");
    if (scene::hasEnvironmentMask(env))
        return fail("the environment already has a mask (an extracted sun, maskRadius " +
                    std::to_string(env.maskRadiusDeg) + " deg); set maskRadius to 0 to extract again");
    auto region = wavelet::findSunRegion(*env.image);
    if (!region) return fail(region.error().reason);

    ExtractedSun out{input, unusedLightName(input), mapToWorld(region->peakDirection, env.rotationDeg), 0.0};
    scene::Environment& masked = out.scene.lighting.environment;
    masked.maskDirection = glm::vec3(region->direction);
    masked.maskRadiusDeg = float(region->radiusRad * 180.0 / kPi);

    // The sun's irradiance: ∫ L cos dω over exactly the texels the mask hides.
    const util::ImageRGB& map = *env.image;
    glm::dvec3 irradiance(0.0);
    double total = 0.0, taken = 0.0;
    for (int y = 0; y < map.height; ++y) {
        const double solidAngle = scene::equirectTexelSolidAngle(map.width, map.height, y);
        for (int x = 0; x < map.width; ++x) {
            const double energy = double(util::luminance(map.at(x, y))) * solidAngle;
            total += energy;
            if (!scene::environmentMaskHides(masked, map.width, map.height, x, y)) continue;
            taken += energy;
            const double cosine = glm::dot(scene::equirectTexelDirection(map.width, map.height, x, y), region->direction);
            irradiance += glm::dvec3(map.at(x, y)) * solidAngle * std::max(0.0, cosine);
        }
    }
    out.energyFraction = total > 0.0 ? taken / total : 0.0;
    const glm::dvec3 tinted = irradiance * glm::dvec3(env.tint) * double(env.intensity);
    const double lum = 0.2126 * tinted.r + 0.7152 * tinted.g + 0.0722 * tinted.b;
    if (!(lum > 0.0)) return fail("the brightest region has no energy once the environment's intensity and tint apply");

    scene::Light sun;
    sun.id = input.nextId();
    sun.name = out.lightName;
    sun.type = scene::LightType::Sun;
    sun.color = glm::vec3(tinted / lum);
    sun.intensity = float(lum);
    sun.direction = glm::vec3(-mapToWorld(region->direction, env.rotationDeg));
    sun.angularDiameterDeg = 2.0f * masked.maskRadiusDeg;
    out.scene.lighting.lights.push_back(sun);
    masked.image = std::make_shared<const util::ImageRGB>(scene::applyEnvironmentMask(map, masked));
    return out;
}

} // namespace wavelit::render
