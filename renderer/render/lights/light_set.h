// The analytic lights of a scene as the path tracer uses them (docs/estimator.md "Analytic
// lights"): one-sample light selection for next-event estimation, the MIS weights between light
// sampling and BSDF sampling, and the emission a BSDF-sampled ray collects on its way.
//
// Choices, and why:
// - Selection is uniform, q = 1/n: the GPU twin needs no table, and a scene's handful of lights
//   differ less in contribution than their powers suggest (a sun's "power" is unbounded).
// - MIS is the power heuristic (β = 2; Veach 1997 §9.2.4) between the light strategy with pdf
//   q · p_light(ω) and the BSDF strategy with pdf p_bsdf(ω); per light, since each light's
//   emission is a separate term of the integrand. Delta lights are reached by light sampling only
//   (weight 1); camera rays (depth 0) see lights with weight 1.
// - Lights are not in the BVH and do not block rays: a ray collects the emission of EVERY
//   light it crosses before its first surface hit, and shadow rays test geometry only. That is
//   the same function from both strategies, so the MIS combination stays unbiased.
// Immutable after construction; safe to share between threads.
#pragma once

#include "render/lights/light_sampler.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace wavelit::render {

// Which strategies reach analytic area lights. Mis is what renders use; LightOnly and BsdfOnly
// are test hooks (all three must agree in the mean). Delta lights use light sampling in all three.
enum class LightStrategy { Mis, LightOnly, BsdfOnly };

// Power heuristic a² / (a² + b²), 0 when both are 0; written as 1 / (1 + (b/a)²) so huge pdfs
// (a 0.53° sun: 1/Ω ≈ 1.5e4 sr⁻¹; GGX r = 0.02: D ≈ 1e6) do not overflow when squared.
float powerHeuristic(float a, float b);

class LightSet {
public:
    explicit LightSet(const std::vector<scene::Light>& lights);

    bool empty() const { return m_lights.empty(); }
    size_t size() const { return m_lights.size(); }
    const LightSampler& light(size_t i) const { return m_lights[i]; }

    // Uniform selection: index min(⌊u n⌋, n − 1), probability 1/n.
    size_t select(float u) const;
    float selectionProbability() const { return m_selection; }

    // MIS weight of a light-sampled direction with light pdf `lightPdf` (solid angle, before
    // selection) and BSDF pdf `bsdfPdf`.
    float lightWeight(const LightSampler& light, float lightPdf, float bsdfPdf,
                      LightStrategy strategy) const;

    // Σ over lights crossed by origin + t·dir, t in (0, tMax) (tMax = infinity: the ray escaped,
    // so the sun counts) of weight × emitted radiance. bsdfPdf: the solid-angle pdf with which the
    // previous vertex sampled dir; cameraRay: no previous vertex, weight 1. perLight (size()
    // entries, or nullptr): each light's term of the sum, written for every light (0 if missed),
    // for the LightMix layers (light_groups.h).
    glm::vec3 emissionAlongRay(const glm::vec3& origin, const glm::vec3& dir, float tMax,
                               float bsdfPdf, bool cameraRay, LightStrategy strategy,
                               glm::vec3* perLight = nullptr) const;

private:
    std::vector<LightSampler> m_lights;
    float m_selection = 0.0f;
};

} // namespace wavelit::render
