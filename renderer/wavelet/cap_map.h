// Local cap domain (architecture.md §4.1, item 2): a spherical cap of half-angle thetaMax around an
// axis (e.g. the reflection vector, the paper's §5.2 frame), mapped from the unit square so that
// narrow lobes get the product's whole resolution instead of one texel of a whole-sphere map.
//
// Map: Shirley-Chiu concentric square -> disk (equal-area), then disk radius rho -> polar angle
// with 1 - cos(theta) = rho^2 (1 - cos thetaMax) (equal-area disk -> cap). The composition is
// equal-area, so the Jacobian is the constant cap solid angle 2 pi (1 - cos thetaMax) and a
// square pdf divided by it is the solid-angle pdf. thetaMax = pi covers the whole sphere.
#pragma once

#include "wavelet/hierarchical_sampler.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace wavelit::wavelet {

// Concentric square [0,1]^2 <-> unit disk, and its inverse (exact, used by invert and lookups).
glm::dvec2 squareToDisk(glm::dvec2 uv);
glm::dvec2 diskToSquare(glm::dvec2 p);

class CapMap {
public:
    CapMap(glm::dvec3 axis, double halfAngle); // axis need not be normalised; halfAngle in (0, pi]

    glm::dvec3 toDirection(glm::dvec2 uv) const;
    std::optional<glm::dvec2> toSquare(glm::dvec3 direction) const; // nullopt outside the cap
    double solidAngle() const { return m_solidAngle; }              // = the Jacobian
    double halfAngle() const { return m_halfAngle; }
    const glm::dvec3& axis() const { return m_axis; }

private:
    glm::dvec3 m_axis, m_t, m_b;
    double m_halfAngle;
    double m_oneMinusCos; // 1 - cos(thetaMax), computed as 2 sin^2(thetaMax/2) for small caps
    double m_solidAngle;
};

// Cap half-angle for a lobe of angular half-width `lobeHalfWidth` (radians, e.g. the angle where
// a GGX lobe falls to a fraction of its peak): `coverage` widths, clamped to the whole sphere.
// Three widths keep the lobe's tail inside the cap; the rest is left to the defensive/MIS part.
double capHalfAngleForLobe(double lobeHalfWidth, double coverage = 3.0);

struct DirectionSample {
    glm::dvec3 direction{0.0};
    double pdf = 0.0; // solid-angle measure
};

// Samples directions inside a cap from a sampler built over the cap's square (e.g. a product of
// factors tabulated through CapMap::toDirection). pdf is 0 outside the cap.
class CapSampler {
public:
    CapSampler(const CapMap& map, HierarchicalSampler sampler)
        : m_map(map), m_sampler(std::move(sampler)) {}

    DirectionSample sample(glm::dvec2 u) const;
    double pdf(glm::dvec3 direction) const;
    const CapMap& map() const { return m_map; }
    const HierarchicalSampler& squareSampler() const { return m_sampler; }

private:
    CapMap m_map;
    HierarchicalSampler m_sampler;
};

} // namespace wavelit::wavelet
