#include "wavelet/sparse_haar.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

// Sums of squares of ~4^n doubles: relative rounding ~4^n * 2^-53 < 1e-9 at n <= 8.
constexpr double kL2Tolerance = 1e-9;

SquareGrid reconstruct(const SparseHaar& s) {
    return inverseHaar(s.toDense());
}

TEST(SparseHaar, ExactSparsifyRoundTrips) {
    util::Pcg32 rng(4);
    SquareGrid g = testing::randomGrid(6, rng);
    HaarImage h = forwardHaar(g);
    SparseHaar s = sparsify(h);
    EXPECT_EQ(s.nonzeroCount(), h.coeffs.size());
    EXPECT_EQ(s.toDense().coeffs, h.coeffs);
    // Breadth-first: levels never decrease along the node array.
    for (size_t i = 1; i < s.nodes.size(); ++i)
        EXPECT_LE(s.nodes[i - 1].level, s.nodes[i].level);
}

TEST(SparseHaar, TruncationReportsTheL2ErrorItLeaves) {
    util::Pcg32 rng(5);
    SquareGrid g = testing::sunSky(7, 40, 90 % 128, 1e3);
    for (double& v : g.values)
        v += 0.1 * rng.nextDouble();
    HaarImage h = forwardHaar(g);
    for (Weighting w : {Weighting::Absolute, Weighting::AreaWeighted}) {
        const size_t keep = h.coeffs.size() / 100;
        Truncation t = truncate(h, keep, w);
        EXPECT_LE(t.kept, keep);
        SquareGrid approx = reconstruct(t.coefficients);
        double err = 0.0;
        for (size_t i = 0; i < g.values.size(); ++i) {
            const double d = g.values[i] - approx.values[i];
            err += d * d;
        }
        err = std::sqrt(err / double(g.values.size())); // L2 over the unit square
        EXPECT_NEAR(err, t.droppedL2, kL2Tolerance * std::max(1.0, err));
        EXPECT_GT(t.relativeL2, 0.0);
        EXPECT_LT(t.relativeL2, 1.0);
    }
}

TEST(SparseHaar, AbsoluteTruncationMinimisesL2AndAreaWeightingPrefersCoarse) {
    util::Pcg32 rng(6);
    SquareGrid g = testing::randomGrid(6, rng);
    HaarImage h = forwardHaar(g);
    Truncation a = truncate(h, 200, Weighting::Absolute);
    Truncation w = truncate(h, 200, Weighting::AreaWeighted);
    EXPECT_LE(a.droppedL2, w.droppedL2);
    double levelA = 0.0, levelW = 0.0;
    for (const SparseNode& node : a.coefficients.nodes)
        for (double d : node.detail)
            levelA += d != 0.0 ? node.level : 0.0;
    for (const SparseNode& node : w.coefficients.nodes)
        for (double d : node.detail)
            levelW += d != 0.0 ? node.level : 0.0;
    EXPECT_LT(levelW, levelA);
}

TEST(SparseHaar, KeepAllIsExactKeepOneIsTheMean) {
    util::Pcg32 rng(7);
    SquareGrid g = testing::randomGrid(4, rng);
    HaarImage h = forwardHaar(g);
    EXPECT_EQ(truncate(h, h.coeffs.size()).droppedL2, 0.0);
    Truncation one = truncate(h, 1);
    EXPECT_EQ(one.kept, 1u);
    EXPECT_TRUE(one.coefficients.nodes.empty());
    EXPECT_DOUBLE_EQ(one.coefficients.scaling, h.scaling());
}

} // namespace
} // namespace wavelit::wavelet
