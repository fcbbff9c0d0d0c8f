// LightMix weights and recombination for `wavelit-cli mix` (docs/lightmix.md): a weight per light
// group, a scalar or an RGB factor, multiplies that group's layer; groups not named keep weight 1;
// the beauty is the sum of the weighted layers (the layers of a --light-groups render sum to its
// beauty, so weights of 1 give the beauty back to float rounding).
#pragma once

#include "scene/exr_layers.h"
#include "util/result.h"

#include <glm/vec3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace wavelit::cli {

using MixWeights = std::vector<std::pair<std::string, glm::vec3>>;

// "sun=2,environment=0.5,key=1:0.8:0.6": comma-separated name=value, value a non-negative finite
// float or r:g:b. Usage errors (exit 2): empty names or values, a malformed or negative number, a
// group named twice.
util::Result<MixWeights> parseMixWeights(const std::string& text);

// Applies `weights` to `image`'s layers (each layer multiplied by its weight) and recomputes the
// beauty as the layers' sum. Error (Invalid, naming `file` and every unknown group, with the
// groups the file has): a weight for a group the file has no layer of; also an image without
// layers (not a --light-groups render).
util::Result<scene::LayeredImage> mixLayers(const scene::LayeredImage& image,
                                            const MixWeights& weights, const std::string& file);

} // namespace wavelit::cli
