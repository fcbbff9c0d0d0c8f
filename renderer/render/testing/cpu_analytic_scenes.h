// Procedural scenes whose rendered radiance is known in closed form (or by 1D quadrature): the
// white furnace (a sphere in a constant environment) and a closed emissive diffuse sphere seen
// from inside. Used by the CPU tracer's tests and tests/furnace_test.cpp, and meant for the GPU
// tracer's analytic tests too, so both are judged on the same geometry.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <memory>

namespace wavelit::render {

// Unit sphere at the origin: `segments` around +Y, `rings` from pole to pole; outward winding
// (counter-clockwise seen from outside) and smooth normals (= positions).
scene::TriangleMesh makeUvSphere(int segments, int rings);

// The square y = 0, |x|, |z| <= halfSize, as two triangles (no vertex normals: the shading
// normal is the geometric one).
scene::TriangleMesh makeGroundQuad(float halfSize);

// One unit sphere with `material`, a constant environment of radiance `environment`, camera at
// (0, 0, 4) looking at the origin with a 40° vertical field of view (the sphere fills ~70% of
// the image height).
std::shared_ptr<scene::Scene> makeFurnaceScene(const scene::Material& material,
                                               const glm::vec3& environment, int segments = 128,
                                               int rings = 64);

// Camera at the centre of a closed unit sphere made of `material`, looking along −Z: every
// path stays inside, so for a Lambert albedo ρ and emission Le the pixel value after B
// scattering events is Le (1 + ρ + … + ρ^B). The environment is black.
std::shared_ptr<scene::Scene> makeClosedSphereScene(const scene::Material& material);

// A 40 m × 40 m plane y = 0 of `material` under a black environment, seen from (0, 3, 3) looking
// at the origin (40° vertical field of view): only the analytic lights a test adds light it.
std::shared_ptr<scene::Scene> makePlaneScene(const scene::Material& material);

} // namespace wavelit::render
