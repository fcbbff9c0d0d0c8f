#include "wavelet/product.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

// Issue 4 acceptance: dense and sparse product pyramids agree to 1e-5 relative. Both paths are
// exact in real arithmetic; what remains is double rounding (~1e-14).
constexpr double kProductTolerance = 1e-5;
// eq 20 and the descent are the same arithmetic up to summation order.
constexpr double kEq20Tolerance = 1e-12;

// Worst relative difference of two pyramids over every level (relative to the level's max).
double pyramidDifference(const ScalingTree& a, const ScalingTree& b) {
    double worst = 0.0;
    for (int l = 0; l <= a.level; ++l) {
        const int side = 1 << l;
        double scale = 0.0, diff = 0.0;
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const double va = a.valueAt(l, x, y), vb = b.valueAt(l, x, y);
                scale = std::max(scale, std::abs(va));
                diff = std::max(diff, std::abs(va - vb));
            }
        if (scale > 0.0)
            worst = std::max(worst, diff / scale);
    }
    return worst;
}

std::vector<SparseHaar> factorsFor(const std::vector<SquareGrid>& grids, double density) {
    std::vector<SparseHaar> out;
    for (const SquareGrid& g : grids)
        out.push_back(testing::truncatedCoefficients(g, density));
    return out;
}

TEST(Product, DenseAndSparseAgreeForRandomFactors) {
    util::Pcg32 rng(11);
    for (int m : {2, 3, 5}) {
        for (double density : {0.02, 0.2, 1.0}) {
            std::vector<SquareGrid> grids;
            for (int k = 0; k < m; ++k)
                grids.push_back(testing::randomGrid(6, rng, 0.0, 2.0));
            auto factors = factorsFor(grids, density);
            auto list = factorPointers(factors);
            const ScalingTree dense = denseProduct(list), sparse = sparseProduct(list);
            EXPECT_LT(pyramidDifference(dense, sparse), kProductTolerance) << m << " " << density;
            EXPECT_NEAR(sparse.integral(), dense.integral(),
                        kProductTolerance * std::abs(dense.integral()));
        }
    }
}

TEST(Product, DenseAndSparseAgreeForStructuredFactors) {
    util::Pcg32 rng(12);
    const int n = 7;
    std::vector<SquareGrid> grids = {testing::sunSky(n, 70, 20, 1e6),
                                     testing::lobe(n, 68.0, 22.0, 3.0),
                                     testing::quarterSupport(n, rng), testing::smoothGrid(n),
                                     testing::lobe(n, 90.0, 100.0, 20.0)};
    for (int m : {2, 3, 5}) {
        std::vector<SquareGrid> g(grids.begin(), grids.begin() + m);
        for (double density : {0.01, 0.05, 1.0}) {
            auto factors = factorsFor(g, density);
            auto list = factorPointers(factors);
            EXPECT_LT(pyramidDifference(denseProduct(list), sparseProduct(list)), kProductTolerance)
                << m << " " << density;
        }
    }
}

TEST(Product, ExactProductEqualsPixelProduct) {
    util::Pcg32 rng(13);
    SquareGrid a = testing::randomGrid(5, rng), b = testing::smoothGrid(5);
    SparseHaar fa = sparsify(forwardHaar(a)), fb = sparsify(forwardHaar(b));
    const SparseHaar* list[] = {&fa, &fb};
    SquareGrid p = sparseProduct(list).toGrid();
    for (size_t i = 0; i < p.values.size(); ++i)
        EXPECT_NEAR(p.values[i], a.values[i] * b.values[i], kProductTolerance * 2.0);
}

TEST(Product, Eq20WithFixedTypoMatchesTheDescent) {
    util::Pcg32 rng(14);
    for (double density : {0.03, 0.3, 1.0}) {
        SparseHaar g = testing::truncatedCoefficients(testing::randomGrid(6, rng), density);
        SparseHaar h = testing::truncatedCoefficients(testing::sunSky(6, 3, 50, 1e4), density);
        const SparseHaar* list[] = {&g, &h};
        EXPECT_LT(pyramidDifference(sparseProductEq20(g, h), sparseProduct(list)), kEq20Tolerance);
    }
}

TEST(Product, InnerAndTripleProductsBothWays) {
    util::Pcg32 rng(15);
    SparseHaar f = testing::truncatedCoefficients(testing::randomGrid(7, rng, -1.0, 1.0), 0.1);
    SparseHaar g = testing::truncatedCoefficients(testing::smoothGrid(7), 0.05);
    SparseHaar h = testing::truncatedCoefficients(testing::sunSky(7, 5, 6, 1e5), 0.02);
    const SparseHaar* two[] = {&f, &g};
    const double dense2 = denseProductIntegral(two);
    EXPECT_NEAR(innerProduct(f, g), dense2, kProductTolerance * std::abs(dense2));
    const double dense3 = denseTripleProduct(f, g, h);
    EXPECT_NEAR(tripleProduct(f, g, h), dense3, kProductTolerance * std::abs(dense3));
    EXPECT_NEAR(tripleProductTripling(f, g, h), dense3, kProductTolerance * std::abs(dense3));
    // Random signed factors at full density exercise every tripling case.
    SparseHaar a = testing::truncatedCoefficients(testing::randomGrid(5, rng, -1.0, 1.0), 1.0);
    SparseHaar b = testing::truncatedCoefficients(testing::randomGrid(5, rng, -1.0, 1.0), 1.0);
    SparseHaar c = testing::truncatedCoefficients(testing::randomGrid(5, rng, -1.0, 1.0), 1.0);
    const double denseAbc = denseTripleProduct(a, b, c);
    EXPECT_NEAR(tripleProductTripling(a, b, c), denseAbc, kProductTolerance * std::abs(denseAbc));
}

TEST(Product, AutoPicksSparseBelowTheCrossoverDensity) {
    util::Pcg32 rng(17);
    std::vector<SparseHaar> sparse = {
        testing::truncatedCoefficients(testing::randomGrid(6, rng), 0.01),
        testing::truncatedCoefficients(testing::smoothGrid(6), 0.01)};
    std::vector<SparseHaar> dense = {
        testing::truncatedCoefficients(testing::randomGrid(6, rng), 1.0),
        testing::truncatedCoefficients(testing::smoothGrid(6), 1.0)};
    EXPECT_LT(meanDensity(factorPointers(sparse)), kSparseCrossoverDensity);
    EXPECT_NEAR(meanDensity(factorPointers(dense)), 1.0, 1e-3); // a few exact zeros at most
    // The sparse path prunes constant squares; the dense path always builds all 5461 nodes.
    EXPECT_LT(product(factorPointers(sparse)).nodes.size(), 5461u);
    EXPECT_EQ(product(factorPointers(sparse), ProductMethod::Dense).nodes.size(), 5461u);
    EXPECT_LT(pyramidDifference(product(factorPointers(dense)),
                                product(factorPointers(dense), ProductMethod::Sparse)),
              kProductTolerance);
}

TEST(Product, SparseFactorsGiveASmallProductTree) {
    util::Pcg32 rng(16);
    SparseHaar a = testing::truncatedCoefficients(testing::randomGrid(9, rng), 0.01);
    SparseHaar b = testing::truncatedCoefficients(testing::smoothGrid(9), 0.01);
    const SparseHaar* list[] = {&a, &b};
    const ScalingTree sparse = sparseProduct(list);
    // A dense pyramid at n = 9 has (4^10 - 1) / 3 = 349525 nodes; 1% factors touch far fewer.
    EXPECT_LT(sparse.nodes.size(), 349525u / 4);
    EXPECT_NEAR(sparse.integral(), denseProduct(list).integral(), kProductTolerance);
}

} // namespace
} // namespace wavelit::wavelet
