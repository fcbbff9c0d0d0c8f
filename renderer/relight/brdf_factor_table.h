// f of one material tabulated once per edit over (view elevation, light direction relative to the
// view) and read by every preview point (docs/relighting.md §7.0b). A roughness edit used to call
// the BRDF plugin ~500 times per point (one per lit texel); for an isotropic BRDF f depends only
// on the view's elevation, the light's elevation and their azimuth difference, so one table of a
// few ten thousand evaluations serves every point. Both the incremental path and a build from
// scratch read the same table (cached equals from scratch stays exact).
#pragma once

#include "plugins/brdf.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace wavelit::relight {

class BrdfFactorTable {
public:
    // f at `params` (and at `black` when given) on the grid; `oneEval`: the grey-affine single
    // evaluation at `red` (ResolvedMaterial::oneEval) gives white in .x and black in .y.
    BrdfFactorTable(const plugins::Brdf& brdf, const plugins::BrdfParams& params, const plugins::BrdfParams* black,
                    bool oneEval, const plugins::BrdfParams& red);
    // f (without the cosine) in the point's local frame, trilinear in the grid's coordinates;
    // `black` receives f at the black parameters when the table holds them.
    glm::vec3 lookup(const glm::vec3& wo, const glm::vec3& wi, glm::vec3* black) const;

    // Whether a BRDF may be tabulated: isotropic in the preview's (arbitrary) tangent frame,
    // glossy (a lambert evaluation is cheaper than the lookup) and no measured table of its own.
    static bool suits(const plugins::Brdf& brdf, const plugins::BrdfParams& params);

    // Grid: a = sqrt(1 - cos theta_o), b = sqrt(1 - cos theta_i) (both near-linear in the angle,
    // so the normal is resolved as finely as the horizon) and c = cos(dphi / 2) (the mirror
    // azimuth dphi = pi at c = 0, where glossy lobes are, resolved finest).
    static constexpr int kA = 32, kB = 64, kC = 48;

private:
    bool m_hasBlack = false;
    std::vector<glm::vec3> m_white, m_black; // [(a * kB + b) * kC + c]
};

} // namespace wavelit::relight
