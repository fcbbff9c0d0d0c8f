// Square images (util::ImageRGB, e.g. from scene::loadImage or resampleEquirect) as SquareGrids,
// validated at the boundary: an image that is not square, not a power of two, finer than
// kMaxLevel or holds a NaN/Inf texel is an Invalid error naming `file` and the problem, never a
// crash deeper in the transforms. Row 0 (the file's top row) is grid row y = 0 (v near 0).
#pragma once

#include "util/image.h"
#include "util/result.h"
#include "wavelet/square_grid.h"

#include <string>

namespace wavelit::wavelet {

// One channel (0 = R, 1 = G, 2 = B).
util::Result<SquareGrid> channelGrid(const util::ImageRGB& image, int channel,
                                     const std::string& file = {});
// Rec.709 luminance 0.2126 R + 0.7152 G + 0.0722 B (architecture.md §6).
util::Result<SquareGrid> luminanceGrid(const util::ImageRGB& image, const std::string& file = {});

} // namespace wavelit::wavelet
