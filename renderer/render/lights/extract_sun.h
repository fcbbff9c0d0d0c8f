// "Extract sun" (docs/lightmix.md): the environment's brightest compact region becomes a `sun`
// light and leaves the map through the environment's mask, so the image stays the same within
// noise while the sun gets the analytic light's direct sampling and can be moved.
//
// The region comes from the map's wavelet tree (wavelet/sun_search.h). The mask is a cap around
// the region's energy centroid; the sun is a disc of the same cap whose irradiance on a plane
// facing it is the masked texels' ∫ L cos dω (× the environment's intensity and tint), so a
// diffuse or rough surface receives the same light, and a mirror sees a uniform disc where the
// map had the sun's own shape. The sun's colour is that energy's, normalised to luminance 1.
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <string>

namespace wavelit::render {

struct ExtractedSun {
    scene::Scene scene;        // the input with the new light and the environment's mask
    std::string lightName;     // "sun", or "sun2"... when a light has that name
    glm::dvec3 peakDirection;  // world space: toward the map's brightest texel
    double energyFraction = 0; // share of the map's luminance energy the sun took
};

// The environment's map must be loaded and not masked yet; `sourceFile` names the scene or setup
// in error messages.
util::Result<ExtractedSun> extractSun(const scene::Scene& scene, const std::string& sourceFile);

// Map frame (rotation 0) to world space for an environment rotated by `rotationDeg` about +Y
// (the inverse of the lookup's rotation, render/lights/cpu_environment.cpp).
glm::dvec3 mapToWorld(const glm::dvec3& mapDirection, float rotationDeg);

} // namespace wavelit::render
