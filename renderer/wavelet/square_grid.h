// SquareGrid: a scalar function on the unit square sampled on a 2^n x 2^n grid of texels (value =
// the function's constant value over the texel). Row y = 0 is the top row of an image file and maps
// to v in [0, 2^-n); column x maps to u. Double precision: grids are build-time inputs of the
// wavelet transforms, whose exactness tests (1e-6 round trips at n = 10) float could not meet.
#pragma once

#include <cstddef>
#include <vector>

namespace wavelit::wavelet {

struct SquareGrid {
    int level = 0; // n: the grid is 2^n x 2^n
    std::vector<double> values;

    SquareGrid() = default;
    explicit SquareGrid(int n, double fill = 0.0) : level(n), values(size_t(1) << (2 * n), fill) {}

    int size() const { return 1 << level; }
    double& at(int x, int y) { return values[size_t(y) * size_t(size()) + size_t(x)]; }
    double at(int x, int y) const { return values[size_t(y) * size_t(size()) + size_t(x)]; }
    // Integral over the unit square: each texel has area 4^-n.
    double integral() const {
        double s = 0.0;
        for (double v : values)
            s += v;
        return s / double(values.size());
    }
};

} // namespace wavelit::wavelet
