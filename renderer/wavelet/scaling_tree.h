// ScalingTree: the scaling-coefficient pyramid F0(l,t) of a function (paper eqs 12-13) as a
// quadtree, the table that hierarchical sampling descends (eqs 14-17).
//
// A node holds F0(l,t) = 2^-l * (average over its square). It either has four children, stored
// contiguously at firstChild in x-major order ((0,0), (1,0), (0,1), (1,1)), or none: then the
// function is constant over the square down to the finest level n (so F0 halves per level below).
// A dense pyramid has every node down to level n; a product of sparse factors stops wherever no
// factor has detail, which is what makes sparse products cheaper than dense ones.
#pragma once

#include "wavelet/sparse_haar.h"
#include "wavelet/square_grid.h"

#include <cstdint>
#include <vector>

namespace wavelit::wavelet {

struct PyramidNode {
    double value = 0.0;      // F0(l, t)
    int32_t firstChild = -1; // -1: constant below
};

struct ScalingTree {
    int level = 0;                  // finest level n
    std::vector<PyramidNode> nodes; // nodes[0] is the root (0, 0, 0)

    // F0(0,0): the integral over the unit square (eq 13).
    double integral() const { return nodes.empty() ? 0.0 : nodes[0].value; }
    // F0(l, x, y) for any l <= level, descending from the root.
    double valueAt(int l, int x, int y) const;
    // Texel values at level n (2^n times the finest scaling coefficients).
    SquareGrid toGrid() const;
    // The Haar coefficients of the same function (details by analysis of each node's children).
    SparseHaar toSparseHaar() const;

    // The full pyramid of a grid (every node down to level n).
    static ScalingTree fromGrid(const SquareGrid& grid);
};

} // namespace wavelit::wavelet
