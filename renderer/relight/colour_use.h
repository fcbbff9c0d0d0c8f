// How a BRDF depends on its baseColor, probed per channel on a fixed set of direction pairs. A
// colour edit of a material whose f is linear or affine in the colour needs no per-point work:
// the preview caches its terms for white (and black) and mixes them per channel when the image is
// summed, as it does a light's power (docs/relighting.md §3).
#pragma once

#include "plugins/brdf.h"

namespace wavelit::relight {

enum class ColourUse {
    Fixed,   // f is not affine in baseColor on the probes: terms at the material's colour
    Ignored, // f does not read baseColor (a measured table): terms at the material's colour
    Linear,  // f(c) = c x f(white) (lambert, glossy): terms at white, times c in the image
    Affine,  // f(c) = f(black) + c x (f(white) - f(black)) (ggx's Schlick F0): both kept
};

const char* colourUseName(ColourUse use);

// Evaluates f at black, white and two mixed colours on a fixed set of (wo, wi) pairs spread over
// the hemisphere and about the mirror direction, with the other parameters of `params`, and
// classifies (relative tolerance 1e-5 per channel). A plugin that were affine on every probe and
// not elsewhere would be previewed with the affine mix; the plugins of plugins/ are exactly so.
ColourUse colourUseOf(const plugins::Brdf& brdf, const plugins::BrdfParams& params);

} // namespace wavelit::relight
