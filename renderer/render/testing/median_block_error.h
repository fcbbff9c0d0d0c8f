// The robust "within noise" measure of the LightMix and extract-sun tests: the median over 4 x 4
// blocks of |mean luminance difference|. A sun's fireflies swing a plain RMSE by ±30% between
// seeds; the median of block errors does not, so tests bound it by a multiple of the
// seed-to-seed figure. Images must have the same size.
#pragma once

#include "util/image.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wavelit::render {

inline double medianBlockError(const util::ImageRGB& a, const util::ImageRGB& b) {
    std::vector<double> errors;
    for (int by = 0; by + 4 <= a.height; by += 4)
        for (int bx = 0; bx + 4 <= a.width; bx += 4) {
            double d = 0.0;
            for (int y = by; y < by + 4; ++y)
                for (int x = bx; x < bx + 4; ++x)
                    d += util::luminance(a.at(x, y)) - util::luminance(b.at(x, y));
            errors.push_back(std::abs(d) / 16.0);
        }
    std::nth_element(errors.begin(), errors.begin() + long(errors.size() / 2), errors.end());
    return errors[errors.size() / 2];
}

} // namespace wavelit::render
