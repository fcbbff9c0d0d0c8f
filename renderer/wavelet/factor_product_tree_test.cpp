#include "wavelet/factor_product_tree.h"
#include "wavelet/product.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

// Against a dense product of all m factors: exact in real arithmetic, double rounding over
// m pairwise products of ~n synthesis levels each stays far below 1e-12 relative (issue 4).
constexpr double kFullRecomputeTolerance = 1e-12;

SparseHaar randomFactor(int n, util::Pcg32& rng, double density) {
    return testing::truncatedCoefficients(testing::randomGrid(n, rng, 0.2, 1.5), density);
}

int ceilLog2(size_t m) {
    int k = 0;
    while ((size_t(1) << k) < m)
        ++k;
    return k;
}

TEST(FactorProductTree, UpdatesRecomputeOnlyThePathAndEqualFullRecomputation) {
    util::Pcg32 rng(21);
    const int n = 5;
    for (size_t m : {1u, 2u, 3u, 4u, 7u, 8u, 16u}) {
        std::vector<SparseHaar> factors;
        for (size_t k = 0; k < m; ++k)
            factors.push_back(randomFactor(n, rng, 0.3));
        FactorProductTree tree(factors);
        EXPECT_EQ(tree.totalProducts(), m - 1);
        EXPECT_FALSE(tree.stale());
        for (int step = 0; step < 12; ++step) {
            const size_t j = rng.nextUint() % m;
            factors[j] = randomFactor(n, rng, 0.3);
            const uint64_t before = tree.factorRevision(j);
            tree.replace(j, factors[j]);
            EXPECT_GT(tree.factorRevision(j), before);
            EXPECT_TRUE(tree.stale());
            const size_t products = tree.update();
            EXPECT_FALSE(tree.stale());
            EXPECT_LE(products, size_t(ceilLog2(m)) + 1) << "m = " << m;
            if ((m & (m - 1)) == 0) {
                EXPECT_EQ(products, size_t(ceilLog2(m))) << "m = " << m; // every path is full depth
            }

            // Bit-exact against a tree rebuilt from scratch (same products in the same order).
            FactorProductTree fresh(factors);
            EXPECT_EQ(tree.product().toDense().coeffs, fresh.product().toDense().coeffs);
            // And against the dense product of all factors.
            const SquareGrid dense = denseProduct(factorPointers(factors)).toGrid();
            const SquareGrid fromTree = tree.productPyramid().toGrid();
            double scale = 0.0, diff = 0.0;
            for (size_t i = 0; i < dense.values.size(); ++i) {
                scale = std::max(scale, std::abs(dense.values[i]));
                diff = std::max(diff, std::abs(dense.values[i] - fromTree.values[i]));
            }
            EXPECT_LE(diff, kFullRecomputeTolerance * scale);
        }
    }
}

TEST(FactorProductTree, BatchedReplacementsAreAllApplied) {
    util::Pcg32 rng(22);
    std::vector<SparseHaar> factors;
    for (int k = 0; k < 8; ++k)
        factors.push_back(randomFactor(4, rng, 1.0));
    FactorProductTree tree(factors);
    factors[1] = randomFactor(4, rng, 1.0);
    factors[6] = randomFactor(4, rng, 1.0);
    tree.replace(1, factors[1]);
    tree.replace(6, factors[6]);
    EXPECT_TRUE(tree.stale());
    EXPECT_EQ(tree.update(), 5u); // two paths of 3 sharing the root
    FactorProductTree fresh(factors);
    EXPECT_EQ(tree.product().toDense().coeffs, fresh.product().toDense().coeffs);
}

TEST(FactorProductTree, IntegralWithChangedFactorIsEq25) {
    util::Pcg32 rng(23);
    std::vector<SparseHaar> factors;
    for (int k = 0; k < 6; ++k)
        factors.push_back(randomFactor(5, rng, 0.5));
    FactorProductTree tree(factors);
    for (size_t j = 0; j < factors.size(); ++j) {
        // <T, F_j> with the current F_j is the full integral...
        EXPECT_NEAR(tree.integralWith(j, factors[j]), tree.integral(),
                    kFullRecomputeTolerance * std::abs(tree.integral()));
        // ...and with a new G it predicts the integral after replacing F_j by G.
        SparseHaar g = randomFactor(5, rng, 0.5);
        const double predicted = tree.integralWith(j, g);
        FactorProductTree copy = tree;
        copy.replace(j, g);
        copy.update();
        EXPECT_NEAR(predicted, copy.integral(),
                    kFullRecomputeTolerance * std::abs(copy.integral()));
    }
}

} // namespace
} // namespace wavelit::wavelet
