// SparseHaar: the nonzero Haar coefficients of a function held as a quadtree of wavelet squares,
// so a top-down descent touches only squares that carry detail (paper §3.2, architecture.md §4).
//
// A node exists for square (l, x, y) iff some kept detail lies at or below it; it stores that
// square's three details (possibly zero when only descendants carry detail) and the index of each
// child node, -1 where the child square has no detail at all (the function is then constant there,
// given by synthesis from the ancestors). Nodes are stored breadth first: sorted by level, and
// within a level by Morton (Z-order) position, so each square's descendants at a level are
// contiguous. Coefficients are doubles and use haar.h's basis and normalisation.
#pragma once

#include "wavelet/haar.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wavelit::wavelet {

struct SparseNode {
    int16_t level = 0;
    int16_t pad = 0;
    int32_t x = 0, y = 0;
    double detail[3] = {0.0, 0.0, 0.0};
    int32_t child[4] = {-1, -1, -1, -1}; // x-major: (0,0), (1,0), (0,1), (1,1)
};

struct SparseHaar {
    int level = 0;                 // n of the 2^n x 2^n domain the coefficients came from
    double scaling = 0.0;          // F0(0,0), the integral over the unit square
    std::vector<SparseNode> nodes; // nodes[0] is the root square when any detail is kept

    int root() const { return nodes.empty() ? -1 : 0; }
    // Number of nonzero coefficients, the scaling coefficient included.
    size_t nonzeroCount() const;
    HaarImage toDense() const;
    // A constant function (all details zero) at resolution n.
    static SparseHaar constant(int n, double scaling);
};

// Every nonzero coefficient of `image` (exact representation).
SparseHaar sparsify(const HaarImage& image);

// How truncation ranks details: by |c| (least L2 error for K terms, Parseval) or by |c| * 2^-l,
// the L1 norm of the term, which favours coarse coefficients that move much energy (Ng et al.
// 2003 use area weighting for lighting).
enum class Weighting { Absolute, AreaWeighted };

struct Truncation {
    SparseHaar coefficients;
    size_t kept = 0;         // coefficients kept, the scaling coefficient included
    double droppedL2 = 0.0;  // L2 norm over the unit square of what was dropped (Parseval)
    double relativeL2 = 0.0; // droppedL2 / L2 norm of the full function (0 for the zero function)
};

// Keeps the scaling coefficient and the keep - 1 largest details by `weighting` (ties broken by
// index so results are reproducible). keep >= the coefficient count keeps everything.
Truncation truncate(const HaarImage& image, size_t keep, Weighting weighting = Weighting::Absolute);

// <F, G> = integral of F G over the unit square from coefficients only (Parseval): the scaling
// product plus the products of details present in both trees. Levels must match.
double innerProduct(const SparseHaar& f, const SparseHaar& g);

} // namespace wavelit::wavelet
