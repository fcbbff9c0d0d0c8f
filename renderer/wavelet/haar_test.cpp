#include "wavelet/haar.h"
#include "wavelet/sparse_haar.h"
#include "wavelet/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::wavelet {
namespace {

// Round trip and Parseval: an orthonormal transform loses ~n * 2^-52 per coefficient; 1e-6 is
// the acceptance bound (ours lands near 1e-15).
constexpr double kRoundTripTolerance = 1e-6;
constexpr double kParsevalTolerance = 1e-6;

double maxRelativeError(const SquareGrid& a, const SquareGrid& b) {
    double worst = 0.0, scale = 0.0;
    for (size_t i = 0; i < a.values.size(); ++i)
        scale = std::max(scale, std::abs(a.values[i]));
    for (size_t i = 0; i < a.values.size(); ++i)
        worst = std::max(worst, std::abs(a.values[i] - b.values[i]) / scale);
    return worst;
}

TEST(Haar, RoundTripAllLevels) {
    util::Pcg32 rng(1);
    for (int n = 0; n <= kMaxLevel; ++n) {
        SquareGrid g = testing::randomGrid(n, rng, -1.0, 3.0);
        SquareGrid back = inverseHaar(forwardHaar(g));
        EXPECT_LT(maxRelativeError(g, back), kRoundTripTolerance) << "n = " << n;
    }
}

TEST(Haar, ScalingCoefficientIsIntegralAndMatchesEq12) {
    util::Pcg32 rng(2);
    SquareGrid g = testing::randomGrid(4, rng);
    HaarImage h = forwardHaar(g);
    EXPECT_NEAR(h.scaling(), g.integral(), 1e-14);
    // A constant function c has F0(0,0) = c and no details.
    HaarImage c = forwardHaar(SquareGrid(5, 2.5));
    EXPECT_DOUBLE_EQ(c.scaling(), 2.5);
    for (size_t i = 1; i < c.coeffs.size(); ++i)
        EXPECT_EQ(c.coeffs[i], 0.0);
}

TEST(Haar, ParsevalInnerProductMatchesPixelSum) {
    util::Pcg32 rng(3);
    for (int n : {1, 3, 6, 9}) {
        SquareGrid f = testing::randomGrid(n, rng, -1.0, 2.0), g = testing::smoothGrid(n);
        double pixel = 0.0;
        for (size_t i = 0; i < f.values.size(); ++i)
            pixel += f.values[i] * g.values[i];
        pixel /= double(f.values.size());
        const double coeff = innerProduct(sparsify(forwardHaar(f)), sparsify(forwardHaar(g)));
        EXPECT_NEAR(coeff, pixel, kParsevalTolerance * std::abs(pixel)) << "n = " << n;
    }
}

TEST(Haar, LevelOfIndexFollowsLayout) {
    EXPECT_EQ(levelOfIndex(0), 0);
    EXPECT_EQ(levelOfIndex(3), 0);
    EXPECT_EQ(levelOfIndex(4), 1);
    EXPECT_EQ(levelOfIndex(15), 1);
    EXPECT_EQ(levelOfIndex(16), 2);
    EXPECT_EQ(levelOfIndex(detailIndex(5, 31, 31, 2)), 5);
}

TEST(Haar, InputValidationNamesTheProblem) {
    auto bad = levelForSize(64, 32, "env.exr");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("not square"), std::string::npos);
    auto npot = levelForSize(48, 48, "env.exr");
    ASSERT_FALSE(npot.ok());
    EXPECT_NE(npot.error().message().find("power of two"), std::string::npos);
    EXPECT_FALSE(levelForSize(2048, 2048).ok());
    EXPECT_EQ(levelForSize(512, 512).value(), 9);
    SquareGrid g(2, 1.0);
    g.at(1, 2) = std::nan("");
    auto nan = checkFinite(g, "a.exr");
    ASSERT_FALSE(nan.ok());
    EXPECT_NE(nan.error().message().find("NaN"), std::string::npos);
    g.at(1, 2) = INFINITY;
    EXPECT_FALSE(checkFinite(g).ok());
}

} // namespace
} // namespace wavelit::wavelet
