// Finding the sun in an environment map (docs/lightmix.md "Extract sun"): the brightest compact
// region, located through the map's wavelet tree and outlined in the map itself.
//
// 1. The map's luminance is splatted energy-preservingly onto the equal-area octahedral square
//    (equirect_resample.h), so a node's scaling coefficient is proportional to the energy its
//    square receives. Descending the scaling-coefficient quadtree from the root, always into the
//    child with the most energy, ends in the leaf the brightest compact source sits in: a sun of
//    10^4 x the sky wins every level, whatever the equirect's distortion near the poles.
// 2. Around that leaf the brightest equirect texel is the peak. The sun is the 8-connected set of
//    texels around the peak brighter than the geometric mean of the peak and the map's median
//    (halfway between sun and sky on a log scale, so the disc and its bright core go, the sky stays).
// 3. Its energy centroid is the sun's direction; the cap radius is the largest angle from it to
//    a region texel's centre plus half that texel's diagonal, so every region texel's centre is
//    inside the cap (the mask's rule, scene/environment_mask.h).
// Maps without a sun (peak under 50 x the median, or a bright region wider than 30 degrees) are
// refused with a message saying which.
#pragma once

#include "util/image.h"
#include "util/result.h"

#include <glm/vec3.hpp>

namespace wavelit::wavelet {

struct SunRegion {
    glm::dvec3 direction{0.0, 1.0, 0.0};     // energy centroid, map frame (rotation 0), unit
    double radiusRad = 0.0;                  // cap around `direction` holding the region
    glm::dvec3 peakDirection{0.0, 1.0, 0.0}; // centre of the brightest texel, map frame
    glm::dvec3 treeDirection{0.0, 1.0, 0.0}; // centre of the leaf the tree descent ended in
    double peakLuminance = 0.0;
    double medianLuminance = 0.0;
    int texels = 0; // texels in the region
};

// `equirect` must be non-empty; `treeLevel` is the octahedral square's level (2^n x 2^n).
util::Result<SunRegion> findSunRegion(const util::ImageRGB& equirect, int treeLevel = 8);

} // namespace wavelit::wavelet
