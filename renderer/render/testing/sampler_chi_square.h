// Chi-square goodness-of-fit for direction samplers whose pdf is piecewise constant on the
// octahedral quadtree (the env, product and oracle samplers) plus smooth BSDF parts.
//
// util/direction_chi_square.h integrates the pdf adaptively on a (theta, phi) grid; a 0.5-degree
// sun 10^6 times the sky is a spike its quadrature can step over. Here the histogram cells are
// octahedral cells (equal area) of the BINNING frame (pass the env-local rotation, so cells align
// with the tables' cells) and expected counts integrate the pdf over every texel of a finer
// octahedral level by the midpoint rule, which is exact for functions constant on those texels.
// Texels whose midpoint value differs from a neighbour's (an edge: the horizon, a product
// leaf below the integration level) are integrated on a 2^refineDepth finer grid, and texels near
// a hot spot (a narrow lobe's axis) on a 2^hotDepth one. Invalid samples form one extra cell with
// expectation N (1 - integral of pdf). Cells are pooled pbrt/Mitsuba style (util/chi_square.h).
#pragma once

#include "util/chi_square.h"
#include "util/direction_chi_square.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace wavelit::render {

struct SphereChiSquareOptions {
    int cellLevel = 5;        // 32^2 histogram cells
    int integrationLevel = 8; // midpoints on 256^2 texels
    int refineDepth = 2;
    int hotDepth = 6;
    std::vector<glm::vec3> hotSpots; // world directions
    double hotRadius = 0.0;          // radians
    // A second kind of hot spot with its own radius and depth (e.g. a one-texel sun, whose
    // texel edges cross the integration texels; 0 radius: none).
    glm::vec3 texelSpot{0.0f, 1.0f, 0.0f};
    double texelSpotRadius = 0.0;
    int texelSpotDepth = 0;
    int samples = 100000;
    uint64_t seed = 7;
    // World -> binning frame (identity by default), e.g. SamplerEnvironment::toLocal.
    std::function<glm::dvec3(const glm::dvec3&)> toBinFrame;
    std::function<glm::dvec3(const glm::dvec3&)> fromBinFrame;
};

// sample(u1, u2, u3): a world direction or nothing (invalid); pdf: solid angle, world direction.
util::DirectionChiSquareResult
sphereChiSquare(const std::function<std::optional<glm::vec3>(float, float, float)>& sample,
                const std::function<double(const glm::vec3&)>& pdf,
                const SphereChiSquareOptions& options);

} // namespace wavelit::render
