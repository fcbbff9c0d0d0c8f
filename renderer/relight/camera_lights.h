// The analytic lights a camera ray sees before its first hit (docs/estimator.md: camera rays see
// lights with weight 1, lights do not block rays): a sphere light's radiance where the ray crosses
// it from outside, a rect light's front face, and the sun's cone when the ray escapes. The
// preview adds it per pixel so a visible light looks as in the path-traced image, averaged over
// 4 x 4 rays across the pixel (the tracer's jittered rays average a light's edge over the pixel;
// one centre ray would make each edge pixel all or nothing). Every sub-ray stops at the distance
// of the pixel's centre hit, which the edge of a light in front of a wall does not change.
#pragma once

#include "relight/preview_points.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

namespace wavelit::relight {

// One light's radiance crossed by origin + t dir, t in (0, tMax) (tMax = infinity: escaped).
glm::vec3 lightSeenAlongRay(const scene::Light& light, const glm::vec3& origin, const glm::vec3& dir,
                            float tMax);

// The mean of lightSeenAlongRay over 4 x 4 rays across pixel (x, y) of the camera's image.
glm::vec3 lightSeenByPixel(const scene::Light& light, const scene::Camera& camera, const CameraRays& rays,
                           int x, int y, float tMax);

} // namespace wavelit::relight
