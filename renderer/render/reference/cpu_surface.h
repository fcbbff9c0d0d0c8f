// The surface rules of docs/estimator.md "Surfaces" in one place, so the CPU tracer and tests
// that predict its output (furnace: the view angle per pixel) use the same normals.
#pragma once

#include "scene/bvh.h"

#include <glm/vec3.hpp>

namespace wavelit::render {

struct SurfacePoint {
    glm::vec3 position;    // origin + t·dir
    glm::vec3 geometric;   // n_g: from the winding, facing the incoming ray
    glm::vec3 shading;     // n_s: interpolated, on n_g's side; n_g when wo is behind it
    float materialIndex;   // v0.w (index into Scene::materials; materials.size() = default)
};

// docs/estimator.md: power(a, b) = a > 0 ? 1 / (1 + (b/a)^2) : 0 (lights.glsl's twin): the MIS
// weight of the CPU tracer's path and next-event terms.
inline float powerWeight(float a, float b) {
    if (!(a > 0.0f)) return 0.0f;
    const float r = b / a;
    return 1.0f / (1.0f + r * r);
}

SurfacePoint surfaceAt(const scene::Bvh& bvh, const scene::BvhHit& hit, const glm::vec3& origin,
                       const glm::vec3& dir);

} // namespace wavelit::render
