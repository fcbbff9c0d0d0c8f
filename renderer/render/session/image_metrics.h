// Error metrics between a render and a reference, for the speed-vs-error report and tests.
#pragma once

#include "util/image.h"

#include <cstddef>

namespace wavelit::render {

// Root-mean-square error over all pixels and channels. Images must have the same size.
double rmse(const util::ImageRGB& image, const util::ImageRGB& reference);

// Relative MSE: mean of (x - ref)^2 / (ref^2 + epsilon), robust to dark pixels (epsilon = 1e-2).
double relativeMse(const util::ImageRGB& image, const util::ImageRGB& reference);

// Number of NaN or infinite channel values.
size_t countNonFinite(const util::ImageRGB& image);

// Mean over all pixels of the channel average.
double meanValue(const util::ImageRGB& image);

} // namespace wavelit::render
