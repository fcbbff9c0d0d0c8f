// Tabulating a function onto a 2^n grid by area averaging: each texel gets the mean of an S x S
// stratified set of point evaluations, so features smaller than a texel keep (approximately)
// their integral instead of being point-sampled in or out. For exact energy preservation of
// images use resampleEquirect (equirect_resample.h), which splats source texels.
#pragma once

#include "wavelet/square_grid.h"

#include <glm/vec2.hpp>

namespace wavelit::wavelet {

template <typename F> SquareGrid tabulate(int n, F&& f, int supersample = 4) {
    SquareGrid grid(n);
    const int side = grid.size();
    const double inv = 1.0 / (double(side) * supersample);
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            double sum = 0.0;
            for (int j = 0; j < supersample; ++j)
                for (int i = 0; i < supersample; ++i)
                    sum += f(glm::dvec2((x * supersample + i + 0.5) * inv,
                                        (y * supersample + j + 0.5) * inv));
            grid.at(x, y) = sum / (supersample * supersample);
        }
    }
    return grid;
}

} // namespace wavelit::wavelet
