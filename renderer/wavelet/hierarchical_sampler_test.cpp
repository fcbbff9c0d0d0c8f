#include "wavelet/defensive_mixture.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/product.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

// Chi-square significance (architecture.md §8, issue 4).
constexpr double kChiSquareAlpha = 0.01;
constexpr int kSamples = 200000;
// pdf(sample) vs the returned pdf: same float tables, products of the same factors in another
// association, so a few double roundings per level.
constexpr double kPdfConsistency = 1e-12;
// invert(sample(u)) vs u: each level's rescaling is undone exactly up to double rounding
// amplified by at most 1/p of the chosen split; 1e-9 leaves room for p ~ 1e-4 over 8 levels.
constexpr double kInvertTolerance = 1e-9;
// Float tables: each level stores two splits, each the smaller probability at 2^-24 relative
// precision; over n = 10 levels the leaf probability drifts by at most 2 * 10 * 2^-24 ~ 1.2e-6
// relative (doubled for the double arithmetic around it).
constexpr double kFloatTableTolerance = 2.0 * 2.0 * 10.0 * 0x1p-24;
// Sum over all 4^10 leaves of their probabilities: 1 up to double summation error.
constexpr double kNormalisationTolerance = 1e-9;
// Monte Carlo: mean of f/pdf within 3 standard errors of the integral.
constexpr double kStandardErrors = 3.0;

ScalingTree productOf(const std::vector<SquareGrid>& grids, double density = 1.0) {
    std::vector<SparseHaar> f;
    for (const SquareGrid& g : grids)
        f.push_back(testing::truncatedCoefficients(g, density));
    return sparseProduct(factorPointers(f));
}

// Builds the sampler, checks chi-square against the clamped, normalised product computed
// independently on texels, and pdf consistency. histLevel <= the tree level.
void expectGoodFit(const ScalingTree& tree, int histLevel, const char* name, uint64_t seed = 1) {
    auto sampler = HierarchicalSampler::build(tree);
    ASSERT_TRUE(sampler.ok()) << name << ": " << sampler.error().message();
    const std::vector<double> expected =
        testing::clampedCellProbabilities(tree.toGrid(), histLevel);
    double mismatch = 0.0;
    const util::ChiSquareResult r =
        testing::chiSquare(*sampler, expected, histLevel, kSamples, seed, &mismatch);
    EXPECT_GT(r.pValue, kChiSquareAlpha)
        << name << ": chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    EXPECT_EQ(r.observedOutsideSupport, 0.0) << name;
    EXPECT_LT(mismatch, kPdfConsistency) << name;
}

TEST(HierarchicalSampler, ChiSquareConstant) {
    expectGoodFit(ScalingTree::fromGrid(SquareGrid(5, 3.0)), 5, "constant");
}

TEST(HierarchicalSampler, ChiSquareRandom) {
    util::Pcg32 rng(31);
    expectGoodFit(ScalingTree::fromGrid(testing::randomGrid(6, rng)), 6, "random");
}

TEST(HierarchicalSampler, ChiSquareSmoothProductOfTwo) {
    util::Pcg32 rng(32);
    expectGoodFit(productOf({testing::smoothGrid(7), testing::smoothGrid(7, 1.0)}), 7,
                  "smooth x smooth");
}

TEST(HierarchicalSampler, ChiSquareHdrSunOneTexel) {
    // Sun at 10^6 x the sky on one texel: it takes 99.6% of the mass at n = 6, the sky's 4095
    // texels share the rest.
    expectGoodFit(ScalingTree::fromGrid(testing::sunSky(6, 17, 9, 1e6)), 6, "hdr sun");
}

TEST(HierarchicalSampler, ChiSquareNearDeltaLobe) {
    // sigma = 0.3 texel: neighbours get exp(-1/0.18) ~ 0.4% of the peak.
    expectGoodFit(ScalingTree::fromGrid(testing::lobe(7, 77.0, 30.0, 0.3)), 7, "near-delta lobe");
}

TEST(HierarchicalSampler, ChiSquareSunTimesLobeBarelyOverlapping) {
    const int n = 7;
    SquareGrid sun = testing::sunSky(n, 40, 40, 1e6);
    SquareGrid narrow = testing::lobe(n, 46.0, 40.0, 1.5); // the sun sits 4 sigma off the lobe
    expectGoodFit(productOf({sun, narrow}), n, "sun x lobe");
}

TEST(HierarchicalSampler, ChiSquareFactorZeroOnThreeQuarters) {
    util::Pcg32 rng(33);
    const int n = 6;
    ScalingTree t = productOf({testing::quarterSupport(n, rng), testing::randomGrid(n, rng)});
    expectGoodFit(t, n, "zero on 3/4");
    // No sample may land where the product is zero.
    auto s = HierarchicalSampler::build(t);
    for (int i = 0; i < 10000; ++i) {
        const SquareSample x = s->sample({rng.nextDouble(), rng.nextDouble()});
        EXPECT_TRUE(x.point.x >= 0.5 && x.point.y >= 0.5);
    }
}

TEST(HierarchicalSampler, ChiSquareTruncatedProductWithNegativeReconstruction) {
    const int n = 7;
    ScalingTree t =
        productOf({testing::sunSky(n, 100, 20, 1e5), testing::lobe(n, 96.0, 24.0, 4.0)}, 0.01);
    const SquareGrid g = t.toGrid();
    double negatives = 0.0;
    for (double v : g.values)
        negatives += v < 0.0;
    ASSERT_GT(negatives, 0.0) << "K = 1% should leave negative reconstructed values";
    expectGoodFit(t, n, "1% truncated");
}

TEST(HierarchicalSampler, ChiSquareThreeAndFiveFactors) {
    util::Pcg32 rng(34);
    const int n = 6;
    std::vector<SquareGrid> g = {testing::randomGrid(n, rng, 0.1, 1.0), testing::smoothGrid(n),
                                 testing::lobe(n, 20.0, 40.0, 8.0), testing::sunSky(n, 22, 38, 1e3),
                                 testing::smoothGrid(n, 2.0)};
    expectGoodFit(productOf({g[0], g[1], g[2]}, 0.05), n, "3 factors");
    expectGoodFit(productOf(g, 0.05), n, "5 factors", 2);
}

TEST(HierarchicalSampler, ChiSquareCoarseUniformLeavesOfASparseTree) {
    // 1% of the coefficients of smooth factors: the product tree stops early in most places and
    // the descent jitters uniformly over large squares.
    const int n = 8;
    ScalingTree t = productOf({testing::smoothGrid(n), testing::lobe(n, 60.0, 200.0, 40.0)}, 0.01);
    ASSERT_LT(t.nodes.size(), size_t(1) << (2 * n));
    expectGoodFit(t, 7, "sparse tree");
}

TEST(HierarchicalSampler, InvertRoundTrips) {
    util::Pcg32 rng(35);
    auto s = HierarchicalSampler::build(
        productOf({testing::randomGrid(8, rng), testing::smoothGrid(8)}));
    ASSERT_TRUE(s.ok());
    for (int i = 0; i < 10000; ++i) {
        const glm::dvec2 u(rng.nextDouble(), rng.nextDouble());
        const glm::dvec2 back = s->invert(s->sample(u).point);
        EXPECT_NEAR(back.x, u.x, kInvertTolerance);
        EXPECT_NEAR(back.y, u.y, kInvertTolerance);
    }
}

TEST(HierarchicalSampler, FloatTablesKeepNormalisationAtLevel10) {
    const int n = 10;
    SquareGrid g = testing::sunSky(n, 700, 300, 1e6);
    g.at(3, 3) = 1e-7; // a texel with a tiny share next to the sun's huge one
    auto s = HierarchicalSampler::build(ScalingTree::fromGrid(g));
    ASSERT_TRUE(s.ok());
    const double total = g.integral() * double(g.values.size());
    const double area = std::ldexp(1.0, -2 * n);
    double sum = 0.0, worst = 0.0;
    for (int y = 0; y < g.size(); ++y)
        for (int x = 0; x < g.size(); ++x) {
            const double p =
                s->pdf({(x + 0.5) * area * g.size(), (y + 0.5) * area * g.size()}) * area;
            const double exact = g.at(x, y) / total;
            sum += p;
            worst = std::max(worst, std::abs(p - exact) / exact);
        }
    EXPECT_NEAR(sum, 1.0, kNormalisationTolerance);
    EXPECT_LT(worst, kFloatTableTolerance);
}

TEST(HierarchicalSampler, AllZeroAndNonFiniteAreReported) {
    auto zero = HierarchicalSampler::build(ScalingTree::fromGrid(SquareGrid(4, 0.0)));
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(zero.error().message().find("all-zero"), std::string::npos);
    auto negative = HierarchicalSampler::build(ScalingTree::fromGrid(SquareGrid(4, -1.0)));
    EXPECT_FALSE(negative.ok());
    SquareGrid bad(3, 1.0);
    bad.at(2, 2) = std::nan("");
    EXPECT_FALSE(HierarchicalSampler::build(ScalingTree::fromGrid(bad)).ok());
}

TEST(HierarchicalSampler, DefensiveMixtureIsUnbiasedForATruncatedApproximation) {
    // The sampler follows a 1%-truncated product; the integrand is the exact product. The wavelet
    // sampler alone can have zero pdf where the integrand is not; the mixture cannot.
    const int n = 7;
    util::Pcg32 rng(36);
    SquareGrid a = testing::sunSky(n, 30, 90, 1e4), b = testing::lobe(n, 33.0, 88.0, 6.0);
    for (double& v : b.values)
        v += 0.01;
    SquareGrid f(n);
    for (size_t i = 0; i < f.values.size(); ++i)
        f.values[i] = a.values[i] * b.values[i];
    const double integral = f.integral();
    auto s = HierarchicalSampler::build(productOf({a, b}, 0.01));
    ASSERT_TRUE(s.ok());
    UniformMixture<HierarchicalSampler> mix(*s, 0.9);
    const int count = 200000;
    double sum = 0.0, sum2 = 0.0, mismatch = 0.0;
    for (int i = 0; i < count; ++i) {
        const SquareSample x = mix.sample({rng.nextDouble(), rng.nextDouble()});
        const int tx = std::min(int(x.point.x * f.size()), f.size() - 1);
        const int ty = std::min(int(x.point.y * f.size()), f.size() - 1);
        const double w = f.at(tx, ty) / x.pdf;
        sum += w;
        sum2 += w * w;
        mismatch = std::max(mismatch, std::abs(mix.pdf(x.point) - x.pdf) / x.pdf);
    }
    const double mean = sum / count, se = std::sqrt((sum2 / count - mean * mean) / count);
    EXPECT_NEAR(mean, integral, kStandardErrors * se) << "se " << se;
    EXPECT_LT(mismatch, kPdfConsistency);
    EXPECT_DOUBLE_EQ(mixturePdf(0.25, 4.0, 2.0), 2.5);
}

} // namespace
} // namespace wavelit::wavelet
