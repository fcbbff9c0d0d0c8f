// SphereSampler: samples directions from a function tabulated on any SphereMap's faces, with an
// exact solid-angle pdf. This is where the two parameterisations differ (architecture.md §3): the
// octahedral map is one square with constant Jacobian 4 pi; the cube map is six squares whose
// texels cover solid angles differing by 5.2x (centre vs corner). Each face's table is the
// function times its texels' solid angle (so the square-domain distribution follows the function
// over the sphere), a face is chosen by its mass, and the pdf of a direction is
// P(face) x square pdf / Jacobian at the point (exact: inside a texel the square density is
// uniform and the map's Jacobian varies smoothly).
#pragma once

#include "util/result.h"
#include "wavelet/cap_map.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/sphere_map.h"

#include <optional>
#include <vector>

namespace wavelit::wavelet {

class SphereSampler {
public:
    // faces: one grid per face of `map` (same level), values >= 0 per unit solid angle (e.g.
    // luminance). Invalid error when every face is zero or a value is not finite. `map` must
    // outlive the sampler.
    static util::Result<SphereSampler> build(const SphereMap& map,
                                             const std::vector<SquareGrid>& faces);

    DirectionSample sample(glm::dvec2 u) const;
    double pdf(glm::dvec3 direction) const;

private:
    const SphereMap* m_map = nullptr;
    std::vector<std::optional<HierarchicalSampler>> m_faces; // empty where a face has no mass
    std::vector<double> m_faceProbability;
};

} // namespace wavelit::wavelet
