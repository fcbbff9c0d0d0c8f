// Environments for the sampler tests and the variance study (issue 6; architecture.md §4.1, §8):
// a synthetic sky with a small sun many times brighter, and bundled env maps box-downsampled to
// a test-sized resolution. Deterministic; no randomness.
#pragma once

#include "scene/scene.h"
#include "util/result.h"

#include <glm/vec3.hpp>

#include <string>

namespace wavelit::render {

// Equirect width x 2width sky (blue-ish gradient above the horizon, dim ground below) with a sun
// disc of `angularDiameterDeg` around unit `sunDirection` (env-local) whose radiance is `ratio`
// times the sky's mean; a sun smaller than a texel occupies the texel containing its centre.
scene::Environment makeSunSkyEnvironment(int width, const glm::vec3& sunDirection, double ratio,
                                         double angularDiameterDeg = 0.53);

// Loads an equirect map and box-filters it by powers of two until it is at most maxWidth wide.
util::Result<scene::Environment> loadDownsampledEnvironment(const std::string& path, int maxWidth);

} // namespace wavelit::render
