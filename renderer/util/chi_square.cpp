#include "util/chi_square.h"

#include <cmath>
#include <limits>

namespace wavelit::util {
namespace {

// Series for P(a, x), valid for x < a + 1 (Numerical Recipes §6.2).
double gammaPSeries(double a, double x) {
    double sum = 1.0 / a, term = sum;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction for Q(a, x), valid for x >= a + 1 (modified Lentz).
double gammaQContinuedFraction(double a, double x) {
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

} // namespace

double regularizedGammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    if (x < a + 1.0) return 1.0 - gammaPSeries(a, x);
    return gammaQContinuedFraction(a, x);
}

double chiSquareSurvival(double statistic, int dof) {
    if (dof <= 0) return 1.0;
    return regularizedGammaQ(0.5 * dof, 0.5 * statistic);
}

double sidakAlpha(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

ChiSquareResult chiSquareTest(std::span<const double> observed, std::span<const double> expected,
                              double minExpected) {
    ChiSquareResult r;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    for (size_t i = 0; i < observed.size() && i < expected.size(); ++i) {
        if (expected[i] <= 0.0) {
            r.observedOutsideSupport += observed[i];
            continue;
        }
        if (expected[i] < minExpected) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            ++r.pooledCells;
            continue;
        }
        double diff = observed[i] - expected[i];
        r.statistic += diff * diff / expected[i];
        ++cells;
    }
    if (pooledExpected > 0.0) {
        double diff = pooledObserved - pooledExpected;
        r.statistic += diff * diff / pooledExpected;
        ++cells;
    }
    r.degreesOfFreedom = cells - 1;
    if (r.observedOutsideSupport > 0.0) {
        r.pValue = 0.0;
        return r;
    }
    r.pValue = chiSquareSurvival(r.statistic, r.degreesOfFreedom);
    return r;
}

} // namespace wavelit::util
