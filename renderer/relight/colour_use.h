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

// For an Affine BRDF: whether f(c) = a + c x b per channel with a and b the same in every channel
// (ggx: Schlick's F0 + (1 - F0) m^5 = m^5 + F0 (1 - m^5) under a grey D G / 4 cos cos). Then one
// evaluation at colour (1, 0, 0) gives both: its red channel is f(white), its green f(black) —
// half the BRDF evaluations of a roughness edit, which were 60% of its time. Probed as
// colourUseOf (1e-5 relative): f(white) and f(black) grey, f(red) = (f(white), f(black), f(black)).
bool greyAffine(const plugins::Brdf& brdf, const plugins::BrdfParams& params);

} // namespace wavelit::relight
