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

SurfacePoint surfaceAt(const scene::Bvh& bvh, const scene::BvhHit& hit, const glm::vec3& origin,
                       const glm::vec3& dir);

} // namespace wavelit::render
