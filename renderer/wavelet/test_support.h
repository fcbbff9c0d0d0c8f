// Test and benchmark inputs for the wavelet core: the hard distributions architecture.md §8 names
// (HDR sun, near-delta lobe, zero regions) as grids, plus a chi-square harness for any sampler
// with sample(dvec2) -> SquareSample. Header-only; not used by production code.
#pragma once

#include "util/chi_square.h"
#include "util/rng.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/sparse_haar.h"
#include "wavelet/square_grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wavelit::wavelet::testing {

// The coefficients of `g` keeping `density` of them (1: all, exactly).
inline SparseHaar truncatedCoefficients(const SquareGrid& g, double density) {
    const HaarImage h = forwardHaar(g);
    if (density >= 1.0)
        return sparsify(h);
    return truncate(h, std::max<size_t>(1, size_t(density * double(h.coeffs.size())))).coefficients;
}

inline SquareGrid randomGrid(int n, util::Pcg32& rng, double lo = 0.0, double hi = 1.0) {
    SquareGrid g(n);
    for (double& v : g.values)
        v = lo + (hi - lo) * rng.nextDouble();
    return g;
}

// Smooth, positive, anisotropic: a stand-in for a diffuse BRDF x cosine factor.
inline SquareGrid smoothGrid(int n, double phase = 0.0) {
    SquareGrid g(n);
    const int s = g.size();
    for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x) {
            const double u = (x + 0.5) / s, v = (y + 0.5) / s;
            g.at(x, y) = 1.2 + std::sin(6.0 * u + phase) * std::cos(4.0 * v - phase);
        }
    return g;
}

// A sky gradient (mean ~1) with a sun on one texel at `ratio` times the sky.
inline SquareGrid sunSky(int n, int sunX, int sunY, double ratio) {
    SquareGrid g(n);
    const int s = g.size();
    for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x)
            g.at(x, y) = 0.5 + double(y) / s + 0.25 * double(x) / s;
    g.at(sunX, sunY) = ratio;
    return g;
}

// A Gaussian lobe centred at texel (cx, cy) with standard deviation sigma texels, floored at 0.
inline SquareGrid lobe(int n, double cx, double cy, double sigma) {
    SquareGrid g(n);
    const int s = g.size();
    for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x) {
            const double dx = x - cx, dy = y - cy;
            g.at(x, y) = std::exp(-(dx * dx + dy * dy) / (2.0 * sigma * sigma));
        }
    return g;
}

// Zero everywhere except the bottom-right quarter (3/4 of the domain is zero).
inline SquareGrid quarterSupport(int n, util::Pcg32& rng) {
    SquareGrid g(n);
    const int s = g.size();
    for (int y = s / 2; y < s; ++y)
        for (int x = s / 2; x < s; ++x)
            g.at(x, y) = 0.2 + rng.nextDouble();
    return g;
}

// Draws `count` samples, histograms them on a 2^histLevel grid and compares with `expected`
// (probability per cell, summing to 1). Also checks every returned pdf against sampler.pdf(p)
// and returns the worst relative mismatch in pdfMismatch.
template <typename Sampler>
util::ChiSquareResult chiSquare(const Sampler& sampler, const std::vector<double>& expected,
                                int histLevel, int count, uint64_t seed,
                                double* pdfMismatch = nullptr) {
    util::Pcg32 rng(seed);
    const int side = 1 << histLevel;
    std::vector<double> observed(expected.size(), 0.0), expectedCounts(expected.size());
    double worst = 0.0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 u(rng.nextDouble(), rng.nextDouble());
        const SquareSample s = sampler.sample(u);
        const int x = std::clamp(int(s.point.x * side), 0, side - 1);
        const int y = std::clamp(int(s.point.y * side), 0, side - 1);
        observed[size_t(y) * side + x] += 1.0;
        if (pdfMismatch) {
            const double p = sampler.pdf(s.point);
            worst = std::max(worst, std::abs(p - s.pdf) / std::max(s.pdf, 1e-300));
        }
    }
    if (pdfMismatch)
        *pdfMismatch = worst;
    for (size_t i = 0; i < expected.size(); ++i)
        expectedCounts[i] = expected[i] * count;
    return util::chiSquareTest(observed, expectedCounts);
}

// Cell probabilities of max(0, f) normalised, f given on a grid of level >= histLevel.
inline std::vector<double> clampedCellProbabilities(const SquareGrid& f, int histLevel) {
    const int side = 1 << histLevel, ratio = f.size() / side;
    std::vector<double> p(size_t(side) * side, 0.0);
    double total = 0.0;
    for (int y = 0; y < f.size(); ++y)
        for (int x = 0; x < f.size(); ++x) {
            const double v = std::max(0.0, f.at(x, y));
            p[size_t(y / ratio) * side + size_t(x / ratio)] += v;
            total += v;
        }
    for (double& v : p)
        v /= total;
    return p;
}

} // namespace wavelit::wavelet::testing
