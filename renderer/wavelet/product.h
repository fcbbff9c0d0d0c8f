// Products of functions held as Haar coefficients: the scaling-coefficient pyramid of
// F = G1 * G2 * ... * Gm (what hierarchical sampling needs, paper §3.4) and product integrals.
//
// Two paths that must agree (architecture.md §4: 1e-5 relative; in practice ~1e-15):
//  - dense: reconstruct every factor to texels, multiply, build the full pyramid. Haar functions
//    are piecewise constant on the finest grid, so this is exact, and costs O(m 4^n).
//  - sparse: a top-down descent over the union of the factors' coefficient trees. Each factor's
//    scaling coefficient is carried down by synthesis; where no factor has detail below a square
//    the product is constant there and the descent stops. This is the multi-function evaluation
//    of Sun & Mukherjee 2006 (all tripling-coefficient cases of Ng 2004 at once) and costs
//    O(m * nodes of the union), independent of 4^n for sparse factors.
// sparseProductEq20 is the paper's eq 20 for two factors, with its typo fixed (the sum runs over
// G^m(l',t') H^m(l',t') for the wavelets under the support of phi(l,t)), kept as a cross-check.
#pragma once

#include "wavelet/scaling_tree.h"
#include "wavelet/sparse_haar.h"

#include <span>
#include <vector>

namespace wavelit::wavelet {

using FactorList = std::span<const SparseHaar* const>;

// The FactorList view of a vector of factors (the vector must outlive the returned pointers).
std::vector<const SparseHaar*> factorPointers(const std::vector<SparseHaar>& factors);

// All factors must have the same level; at least one factor.
ScalingTree denseProduct(FactorList factors);
ScalingTree sparseProduct(FactorList factors);
ScalingTree sparseProductEq20(const SparseHaar& g, const SparseHaar& h);

// Picks the faster path per case (architecture.md §4: keep both, pick per case): sparse when the
// factors' mean coefficient density is below kSparseCrossoverDensity. Measured crossovers
// (docs/wavelet-benchmarks.md): ~35% at 64^2, ~15% at 256^2, none at 512^2 (sparse always
// faster); 15% is right or within 1.3x everywhere.
enum class ProductMethod { Auto, Dense, Sparse };
constexpr double kSparseCrossoverDensity = 0.15;
double meanDensity(FactorList factors); // nonzero coefficients / 4^n, averaged over factors
ScalingTree product(FactorList factors, ProductMethod method = ProductMethod::Auto);

// Integral over the unit square of the product of the factors.
double denseProductIntegral(FactorList factors);  // texel sums
double sparseProductIntegral(FactorList factors); // Parseval for 2, the descent for more

// <F,G,H> both ways (the paper's triple product integral). tripleProductTripling sums the
// non-zero tripling coefficients C_ijk case by case (paper §3.2 / Ng 2004): all three scaling;
// three different wavelet types on one square (C = 2^l); two identical wavelets with the third a
// coarser function (sum over those = the third factor's average over the square).
double tripleProduct(const SparseHaar& f, const SparseHaar& g, const SparseHaar& h);
double tripleProductTripling(const SparseHaar& f, const SparseHaar& g, const SparseHaar& h);
double denseTripleProduct(const SparseHaar& f, const SparseHaar& g, const SparseHaar& h);

} // namespace wavelit::wavelet
