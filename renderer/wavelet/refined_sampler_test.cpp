#include "wavelet/defensive_mixture.h"
#include "wavelet/product.h"
#include "wavelet/refined_sampler.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

constexpr double kChiSquareAlpha = 0.01;
constexpr int kSamples = 1000000;
// Same tables on both sides; a few double roundings per level of two descents.
constexpr double kPdfConsistency = 1e-12;
constexpr double kStandardErrors = 3.0;

// Averages a fine grid down to level n (box filter: keeps the integral).
SquareGrid downsample(const SquareGrid& fine, int n) {
    SquareGrid g(n);
    const int r = fine.size() / g.size();
    for (int y = 0; y < fine.size(); ++y)
        for (int x = 0; x < fine.size(); ++x)
            g.at(x / r, y / r) += fine.at(x, y) / double(r * r);
    return g;
}

struct RefinedCase {
    SquareGrid env;      // 512^2 with a one-texel sun
    SquareGrid brdf;     // 32^2 lobe
    ScalingTree product; // 32^2 product of the downsampled env and the lobe
    ScalingTree envTree; // 512^2 pyramid
};

RefinedCase makeSetup() {
    RefinedCase s;
    s.env = testing::sunSky(9, 301, 77, 1e6);
    s.brdf = testing::lobe(5, 18.0, 5.0, 4.0);
    for (double& v : s.brdf.values)
        v += 0.05;
    SparseHaar e = sparsify(forwardHaar(downsample(s.env, 5))), b = sparsify(forwardHaar(s.brdf));
    const SparseHaar* list[] = {&e, &b};
    s.product = sparseProduct(list);
    s.envTree = ScalingTree::fromGrid(s.env);
    return s;
}

// The refined distribution in closed form on the fine grid: P(product leaf) x env's share of the
// leaf's mass (uniform where the env has none).
std::vector<double> refinedProbabilities(const RefinedCase& s) {
    const SquareGrid coarse = s.product.toGrid();
    const int fineSide = s.env.size(), r = fineSide / coarse.size();
    double total = 0.0;
    for (double v : coarse.values)
        total += std::max(0.0, v);
    const SquareGrid envCoarse = downsample(s.env, s.product.level);
    std::vector<double> p(size_t(fineSide) * fineSide);
    for (int y = 0; y < fineSide; ++y)
        for (int x = 0; x < fineSide; ++x) {
            const double leaf = std::max(0.0, coarse.at(x / r, y / r)) / total;
            const double share = s.env.at(x, y) / (envCoarse.at(x / r, y / r) * r * r);
            p[size_t(y) * fineSide + x] = leaf * share;
        }
    return p;
}

TEST(RefinedSampler, ChiSquareAtTheFineResolutionWithAOneTexelSun) {
    const RefinedCase s = makeSetup();
    auto product = HierarchicalSampler::build(s.product);
    auto env = HierarchicalSampler::build(s.envTree);
    ASSERT_TRUE(product.ok() && env.ok());
    RefinedSampler refined(*product, *env);
    double mismatch = 0.0;
    const util::ChiSquareResult r =
        testing::chiSquare(refined, refinedProbabilities(s), 9, kSamples, 41, &mismatch);
    EXPECT_GT(r.pValue, kChiSquareAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    EXPECT_EQ(r.observedOutsideSupport, 0.0);
    EXPECT_LT(mismatch, kPdfConsistency);
}

TEST(RefinedSampler, InvertRoundTrips) {
    // 1e-6: the sun's split (p ~ 1e-3 for the sky side) amplifies double rounding in u by 1/p
    // per level over 9 levels of two descents.
    constexpr double kInvertTolerance = 1e-6;
    const RefinedCase s = makeSetup();
    auto product = HierarchicalSampler::build(s.product);
    auto env = HierarchicalSampler::build(s.envTree);
    RefinedSampler refined(*product, *env);
    util::Pcg32 rng(44);
    for (int i = 0; i < 10000; ++i) {
        const glm::dvec2 u(rng.nextDouble(), rng.nextDouble());
        const glm::dvec2 back = refined.invert(refined.sample(u).point);
        EXPECT_NEAR(back.x, u.x, kInvertTolerance);
        EXPECT_NEAR(back.y, u.y, kInvertTolerance);
    }
}

TEST(RefinedSampler, EstimatorIsUnbiasedAndBeatsTheUnrefinedProduct) {
    // Integrand: the fine env x the BRDF (constant over each 32^2 texel).
    const RefinedCase s = makeSetup();
    auto product = HierarchicalSampler::build(s.product);
    auto env = HierarchicalSampler::build(s.envTree);
    RefinedSampler refined(*product, *env);
    UniformMixture<RefinedSampler> mix(refined, 0.9);
    const int fine = s.env.size(), r = fine / s.brdf.size();
    auto f = [&](glm::dvec2 p) {
        const int x = std::min(int(p.x * fine), fine - 1), y = std::min(int(p.y * fine), fine - 1);
        return s.env.at(x, y) * s.brdf.at(x / r, y / r);
    };
    double integral = 0.0;
    for (int y = 0; y < fine; ++y)
        for (int x = 0; x < fine; ++x)
            integral += s.env.at(x, y) * s.brdf.at(x / r, y / r);
    integral /= double(fine) * fine;

    auto estimate = [&](auto&& sampler, double& se) {
        util::Pcg32 rng(42);
        const int count = 100000;
        double sum = 0.0, sum2 = 0.0;
        for (int i = 0; i < count; ++i) {
            const SquareSample x = sampler.sample({rng.nextDouble(), rng.nextDouble()});
            const double w = f(x.point) / x.pdf;
            sum += w;
            sum2 += w * w;
        }
        const double mean = sum / count;
        se = std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count);
        return mean;
    };
    double seRefined = 0.0, seCoarse = 0.0;
    const double mean = estimate(mix, seRefined);
    EXPECT_NEAR(mean, integral, kStandardErrors * seRefined);
    UniformMixture<HierarchicalSampler> coarseOnly(*product, 0.9);
    const double meanCoarse = estimate(coarseOnly, seCoarse);
    EXPECT_NEAR(meanCoarse, integral, kStandardErrors * seCoarse + 1e-12);
    // architecture.md §4.1: refinement is what makes a sub-texel sun cheap (hundreds of times less
    // variance); assert only the direction, the figure goes to the report.
    EXPECT_LT(seRefined, seCoarse);
    std::printf("refined 32^2 x 512^2 sun: se %.3g vs unrefined %.3g (variance ratio %.0fx)\n",
                seRefined, seCoarse, (seCoarse * seCoarse) / (seRefined * seRefined));
}

TEST(RefinedSampler, UniformInsideLeavesWhereTheFineFactorHasNoMass) {
    // The fine factor is zero in the left half; the product is not. Samples landing there must be
    // uniform inside their product leaf, with the pdf saying so.
    SquareGrid fine(6, 1.0);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 32; ++x)
            fine.at(x, y) = 0.0;
    auto product = HierarchicalSampler::build(ScalingTree::fromGrid(SquareGrid(3, 1.0)));
    auto env = HierarchicalSampler::build(ScalingTree::fromGrid(fine));
    RefinedSampler refined(*product, *env);
    std::vector<double> expected(64 * 64, 1.0 / 4096.0);
    const util::ChiSquareResult r = testing::chiSquare(refined, expected, 6, 200000, 43);
    EXPECT_GT(r.pValue, kChiSquareAlpha);
}

} // namespace
} // namespace wavelit::wavelet
