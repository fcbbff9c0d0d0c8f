// Directional albedo E(wo) = ∫ f(wo, wi) cosθi dwi by dense deterministic quadrature: the
// reference against which BRDF sampling (plugins/*_test.cpp) and the furnace renders
// (tests/furnace_test.cpp) are checked. Independent of sample(): it only calls eval().
//
// The integral is taken over half vectors h (wi = reflect(−wo, h), dwi = 4 (wo·h) dh), with
// θh = (π/2) t³ on a t grid, so a GGX peak at r = 0.02 (alpha = 4e-4) spans ~20 cells; for any
// reflection BRDF the map h ↦ wi covers the upper hemisphere exactly once. 2-point Gauss–Legendre
// per cell. Measured: 256² cells agree with 768² cells to < 5e-5 relative; the horizon cut is a
// kink inside cells that limits the order (plugins/brdf_test.cpp QuadratureIsConverged).
#pragma once

#include "plugins/brdf.h"

#include <glm/vec3.hpp>

namespace wavelit::plugins {

// wo: unit, local frame (z = normal). Returns E per channel (0 when wo.z <= 0).
glm::dvec3 directionalAlbedo(const Brdf& brdf, const BrdfParams& params, const glm::vec3& wo,
                             int thetaCells = 256, int phiCells = 256);

} // namespace wavelit::plugins
