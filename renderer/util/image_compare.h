// Pixel-by-pixel comparison of two images of the same size: how the relighting preview's cached
// result is checked against a from-scratch computation (tests, and `wavelit-cli relight`'s report).
#pragma once

#include "util/image.h"

#include <algorithm>
#include <cmath>

namespace wavelit::util {

// Largest |a − b| / max(|b|, 1e-6) over pixels and channels (b the reference).
inline double maxRelativeDifference(const ImageRGB& a, const ImageRGB& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = a.pixels[i][c], y = b.pixels[i][c];
            worst = std::max(worst, std::abs(x - y) / std::max(std::abs(y), 1e-6));
        }
    return worst;
}

} // namespace wavelit::util
