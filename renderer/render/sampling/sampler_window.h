// ProductWindow: the part of the octahedral square a product sampler covers (architecture.md §4.1,
// item 2: fit the product's domain to the lobe).
//
// A window is a square of side 2^-k whose origin lies on the grid of step 2^-(k+1) (half its
// side), so a 2^m product grid over it (m >= 1) is made of exact cells of the global octahedral
// quadtree at level k + m: product leaves are global cells, and the environment's own pyramid
// refines them with an exact pdf (RefinedSampler's idea, with the product living on a sub-square).
// This is the paper's "environment localised around the reflection vector" (§5.2) expressed in
// the global equal-area map rather than in a rotated frame: the localised images of all
// reflection directions are windows of ONE pyramid, so refinement below the product's resolution
// needs no per-direction fine tables. k = 0 (origin 0) is the whole sphere.
// Pure functions; thread-safe.
#pragma once

#include "wavelet/sphere_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace wavelit::render {

struct ProductWindow {
    int k = 0;      // side = 2^-k
    int ox = 0;     // origin.x in units of 2^-(k+1)
    int oy = 0;     // origin.y in units of 2^-(k+1)

    double side() const;
    glm::dvec2 origin() const;
    bool whole() const { return k == 0; }
    // Square point -> window-local [0,1)^2, or false when outside the window.
    bool toLocal(glm::dvec2 p, glm::dvec2& local) const;
    glm::dvec2 toGlobal(glm::dvec2 local) const;
    // Global cell (level k + l) of window cell (l, x, y); l >= 1.
    void globalCell(int l, int x, int y, int& gl, int& gx, int& gy) const;
};

// Caps wider than this use the whole sphere: their square image is not compact.
inline constexpr double kWholeSphereCapAngle = 1.2; // radians (~69 degrees)

// The smallest window (k <= maxK) that contains the octahedral image of the cap of half-angle
// `halfAngle` around unit `axis` (probed on rings; a cap straddling a fold of the map, whose image
// is not compact, gets the whole square).
ProductWindow chooseWindow(const wavelet::OctahedralMap& map, const glm::dvec3& axis,
                           double halfAngle, int maxK);

} // namespace wavelit::render
