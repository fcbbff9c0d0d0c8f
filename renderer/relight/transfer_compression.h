// A point's transfer T on the sphere grid, from texel values to its K largest Haar coefficients
// (the sparse form the preview keeps and dots with L and the lights; docs/relighting.md §2).
#pragma once

#include "relight/point_transfer.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace wavelit::relight {

// Haar analysis of `texels` (a 2^level × 2^level grid, already scaled to finest scaling
// coefficients) and the `keep` largest coefficients by luminance-weighted magnitude, the scaling
// coefficient always among them. `texels` is clobbered.
void compress(std::vector<glm::dvec3>& texels, int level, size_t keep, SparseTransfer& out);

// compress() for a grey T (a grey-affine BRDF's f(white) and f(black), ResolvedMaterial::oneEval):
// one channel, a third of the transform, the same coefficients.
void compressGrey(std::vector<double>& texels, int level, size_t keep, SparseTransfer& out);

// compress(), or compressGrey() when every texel is grey.
void compressMaybeGrey(std::vector<glm::dvec3>& texels, int level, size_t keep, SparseTransfer& out);

} // namespace wavelit::relight
