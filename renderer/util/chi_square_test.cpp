#include "util/chi_square.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace wavelit::util {
namespace {

// Closed forms: for 2 degrees of freedom the survival is exp(-x/2); for 1 it is erfc(sqrt(x/2)).
TEST(ChiSquare, SurvivalMatchesClosedForms) {
    for (double x : {0.1, 1.0, 3.0, 10.0, 40.0}) {
        EXPECT_NEAR(chiSquareSurvival(x, 2), std::exp(-0.5 * x), 1e-12);
        EXPECT_NEAR(chiSquareSurvival(x, 1), std::erfc(std::sqrt(0.5 * x)), 1e-12);
    }
}

TEST(ChiSquare, AcceptsSamplesFromTheTestedDistributionAndRejectsAnother) {
    Pcg32 rng(7);
    const int cells = 20, n = 100000;
    std::vector<double> observed(cells, 0.0), expected(cells, double(n) / cells);
    for (int i = 0; i < n; ++i) observed[rng.nextUint() % cells] += 1.0;
    EXPECT_GT(chiSquareTest(observed, expected).pValue, 0.01);

    std::vector<double> skewed(cells, 0.0);
    for (int i = 0; i < n; ++i) {
        float u = rng.nextFloat();
        skewed[std::min(cells - 1, int(u * u * cells))] += 1.0;
    }
    EXPECT_LT(chiSquareTest(skewed, expected).pValue, 1e-6);
}

TEST(ChiSquare, SamplesWhereExpectationIsZeroFail) {
    std::vector<double> observed{10, 10, 1}, expected{10.5, 10.5, 0};
    auto r = chiSquareTest(observed, expected);
    EXPECT_EQ(r.pValue, 0.0);
    EXPECT_EQ(r.observedOutsideSupport, 1.0);
}

} // namespace
} // namespace wavelit::util
