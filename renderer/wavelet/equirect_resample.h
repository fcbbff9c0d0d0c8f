// Resampling an equirectangular environment (architecture.md §3: u = 0.5 + atan2(d.z, d.x) / 2 pi,
// v = acos(d.y) / pi, row 0 at the top) onto a sphere map's 2^n x 2^n face grids.
//
// Energy-preserving splatting rather than point lookups: every source texel is cut into S x S
// sub-cells, each carrying radiance x its exact solid angle into the target texel its centre
// falls in; a target texel's radiance is its collected energy over its exact solid angle. So the
// integral over the sphere is preserved exactly (up to float output), and a one-texel sun keeps
// all its energy whatever the resolutions. S grows where source texels are large compared with
// target ones (the equator of a coarse source), so no target texel is left without samples.
#pragma once

#include "util/image.h"
#include "wavelet/sphere_map.h"

#include <vector>

namespace wavelit::wavelet {

// One ImageRGB (2^n x 2^n, radiance) per face of `map`. `env` must be non-empty.
std::vector<util::ImageRGB> resampleEquirect(const util::ImageRGB& env, const SphereMap& map,
                                             int n);

// Integral over the sphere of an equirect map (sum of radiance x texel solid angle), per channel.
glm::dvec3 equirectEnergy(const util::ImageRGB& env);
// The same for face grids produced by resampleEquirect.
glm::dvec3 faceEnergy(const std::vector<util::ImageRGB>& faces, const SphereMap& map);

} // namespace wavelit::wavelet
