// The analytic lights a camera ray sees before its first hit (docs/estimator.md: camera rays see
// lights with weight 1, lights do not block rays): a sphere light's radiance where the ray crosses
// it from outside, a rect light's front face, and the sun's cone when the ray escapes. The
// preview adds it per pixel so a visible light looks as in the path-traced image.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

namespace wavelit::relight {

// Sum over the lights crossed by origin + t dir, t in (0, tMax) (tMax = infinity: escaped).
glm::vec3 lightsSeenByCamera(const scene::Scene& scene, const glm::vec3& origin, const glm::vec3& dir,
                             float tMax);

} // namespace wavelit::relight
