// Pearson chi-square goodness-of-fit, pbrt/Mitsuba style: cells whose expected count is below
// kMinExpected are pooled into one cell, so sparse tails do not dominate the statistic.
#pragma once

#include <cstddef>
#include <span>

namespace wavelit::util {

struct ChiSquareResult {
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 1.0;     // probability of a statistic at least this large under H0
    int pooledCells = 0;     // how many low-expectation cells were merged
    double observedOutsideSupport = 0.0; // counts in cells with zero expectation (must be 0)
};

// observed[i], expected[i] are counts over the same cells; sum(expected) should equal the number
// of samples. Cells with expected == 0 and observed > 0 make the test fail with p = 0.
ChiSquareResult chiSquareTest(std::span<const double> observed, std::span<const double> expected,
                              double minExpected = 5.0);

// Upper regularized incomplete gamma Q(a, x) = Γ(a, x) / Γ(a); chi-square survival is Q(k/2, x/2).
double regularizedGammaQ(double a, double x);
double chiSquareSurvival(double statistic, int degreesOfFreedom);

// Šidák-corrected per-test significance when `tests` independent tests share `alpha` overall.
double sidakAlpha(double alpha, int tests);

} // namespace wavelit::util
