// Chi-square goodness-of-fit of a direction sampler against its own pdf over the whole sphere
// (architecture.md §8, pbrt-v4's bsdfs_test style). Shared by the BRDF plugins and the render-layer
// samplers (issue 6), so every sampler is judged by the same histogram and the same integration.
//
// Cells are a (θ, φ) grid around `axis` with θ = π t^p, t uniform over the θ bins: p = 1 is a plain
// polar grid, p = 2–3 puts fine cells near the axis so that a mirror-like lobe (GGX r = 0.02, a
// lobe ~1e-3 rad wide) is resolved — aim the axis at the lobe (e.g. the reflection vector).
// Expected counts integrate the pdf over each cell in (t, φ): sub×sub subcells, each by adaptive
// 2×2 Gauss–Legendre (split while splitting matters at 1% of the cell's Poisson noise, so cells
// cut by the horizon or a narrow lobe are integrated as finely as they need); invalid samples (sampler returns nothing) form one extra cell whose
// expectation is N (1 − ∫pdf), so the lost mass is tested too.
#pragma once

#include "util/chi_square.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <optional>

namespace wavelit::util {

struct DirectionGrid {
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
    int thetaBins = 32;
    int phiBins = 64;
    double thetaExponent = 1.0; // p in θ = π t^p
    int subdivisions = 2;       // initial integration subcells per cell and axis
};

struct DirectionChiSquareResult {
    ChiSquareResult chi;
    double integratedPdf = 0.0; // ∫ pdf over the sphere (1 minus the invalid mass)
    int invalidSamples = 0;
};

// sample(u) returns a unit direction or nothing (invalid sample); pdf(w) is in solid angle.
// Draws `samples` directions with u from Pcg32(seed).
DirectionChiSquareResult
directionChiSquare(const std::function<std::optional<glm::vec3>(glm::vec2)>& sample,
                   const std::function<double(const glm::vec3&)>& pdf, const DirectionGrid& grid,
                   int samples, uint64_t seed);

} // namespace wavelit::util
