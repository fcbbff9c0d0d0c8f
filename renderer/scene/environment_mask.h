// The environment's mask (docs/lightmix.md "Extract sun"): a cap over the map, in the map's own
// frame (rotation 0), whose texels count as black because their energy moved into a sun light.
// The map file is never changed: the mask is applied where the map is loaded (scene_io.cpp), so
// both tracers, their sampling tables and the relighting preview all see the masked map.
// A texel is masked when its centre direction lies inside the cap; the sun's energy is summed
// with the same rule (render/lights/extract_sun.cpp), so what leaves the map is what the sun gets.
#pragma once

#include "util/image.h"

#include <glm/vec3.hpp>

namespace wavelit::scene {

struct Environment;

// The unit direction, in the map's frame, of the centre of texel (x, y) of a w x h equirect map
// (architecture.md §3: u = 0.5 + atan2(d.z, d.x) / 2 pi, v = acos(d.y) / pi).
glm::dvec3 equirectTexelDirection(int width, int height, int x, int y);

// Solid angle of texel row y of a w x h equirect map.
double equirectTexelSolidAngle(int width, int height, int y);

// True when the environment has a mask (maskRadiusDeg > 0).
bool hasEnvironmentMask(const Environment& env);

// True when texel (x, y) of a w x h map lies under the environment's mask.
bool environmentMaskHides(const Environment& env, int width, int height, int x, int y);

// `map` with the texels under the environment's mask set to black.
util::ImageRGB applyEnvironmentMask(const util::ImageRGB& map, const Environment& env);

} // namespace wavelit::scene
