// Nonstandard orthonormal 2D Haar transform on the unit square (paper §3.1, Stollnitz et al.).
//
// Basis: the scaling function phi(0,0) = 1 on [0,1]^2 and, for each level l in [0, n) and square
// t = (x, y) in [0, 2^l)^2, three wavelets psi^m(l,t), m = 0 (difference in x), 1 (difference in
// y), 2 (diagonal), each +-2^l on the square's quarters. Coefficients are inner products with the
// basis, so a function's scaling coefficient at (l, t) is F0(l,t) = 2^-l * (average over the
// square) and F0(0,0) is the integral (architecture.md §4, eqs 12-13).
//
// Dense coefficient layout (also the sort order of sparse coefficients): index 0 holds F0(0,0);
// the details of level l occupy [4^l, 4^(l+1)), ordered by position (row-major) then m. So a
// sort by index is a sort by (level, position), and coarse-to-fine descents read in order.
#pragma once

#include "util/result.h"
#include "wavelet/square_grid.h"

#include <cstddef>
#include <string>
#include <vector>

namespace wavelit::wavelet {

// 2^10 = 1024 texels per side: 1M coefficients in double (8 MiB) per factor; finer tables cost
// more than the sampler gains (architecture.md §4.1 refines below the product resolution instead).
constexpr int kMaxLevel = 10;

struct HaarImage {
    int level = 0;              // n
    std::vector<double> coeffs; // 4^n entries, layout above

    int size() const { return 1 << level; }
    double scaling() const { return coeffs[0]; }
};

inline size_t detailIndex(int l, int x, int y, int m) {
    return (size_t(1) << (2 * l)) + 3 * ((size_t(y) << l) + size_t(x)) + size_t(m);
}

// Level of a coefficient index (0 for the scaling coefficient and for level-0 details).
int levelOfIndex(size_t index);

// One synthesis step: the scaling coefficients of the four children (x-major: (0,0), (1,0),
// (0,1), (1,1)) of a square with scaling coefficient s and details d[0..2].
inline void haarSynthesize(double s, const double d[3], double child[4]) {
    child[0] = 0.5 * (s + d[0] + d[1] + d[2]);
    child[1] = 0.5 * (s - d[0] + d[1] - d[2]);
    child[2] = 0.5 * (s + d[0] - d[1] - d[2]);
    child[3] = 0.5 * (s - d[0] - d[1] + d[2]);
}

// The inverse of haarSynthesize (the 4x4 Hadamard matrix / 2 is its own inverse).
inline void haarAnalyze(const double child[4], double& s, double d[3]) {
    s = 0.5 * (child[0] + child[1] + child[2] + child[3]);
    d[0] = 0.5 * (child[0] - child[1] + child[2] - child[3]);
    d[1] = 0.5 * (child[0] + child[1] - child[2] - child[3]);
    d[2] = 0.5 * (child[0] - child[1] - child[2] + child[3]);
}

HaarImage forwardHaar(const SquareGrid& grid);
SquareGrid inverseHaar(const HaarImage& image);

// Input validation for grids that come from files: the level for a width x height image, or an
// Invalid error naming `file` when it is not square, not a power of two or finer than kMaxLevel.
util::Result<int> levelForSize(int width, int height, const std::string& file = {});
// Invalid error naming the first NaN/Inf texel.
util::Status checkFinite(const SquareGrid& grid, const std::string& file = {});

} // namespace wavelit::wavelet
