// GuidedCdf (guided_cdf.h): every draw equals a plain binary search of the CDF (zero weights,
// 1e6 spikes, all-zero input), the rescaled u stays in [0, 1) and increases with u inside an
// entry, and — the reason it replaced the alias tables — N evenly spread u's draw each entry
// N p within one.
#include "render/sampling/guided_cdf.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wavelit::render {
namespace {

int bruteForce(const std::vector<double>& w, double u) {
    double total = 0.0;
    for (double x : w) total += x;
    double sum = 0.0;
    for (size_t i = 0; i < w.size(); ++i) {
        sum += w[i];
        if (w[i] > 0.0 && u * total < sum) return int(i);
    }
    return -1;
}

std::vector<std::vector<double>> hardWeights() {
    std::vector<std::vector<double>> cases;
    util::Pcg32 rng(3);
    for (int c = 0; c < 6; ++c) {
        std::vector<double> w(size_t(7 + 37 * c));
        for (double& x : w) x = rng.nextDouble() < 0.3 ? 0.0 : std::pow(rng.nextDouble(), 4.0);
        w[size_t(c) % w.size()] = 1e6; // a sun
        cases.push_back(w);
    }
    cases.push_back({0.0, 0.0, 5.0, 0.0, 0.0}); // one entry
    cases.push_back({1e-300, 1.0, 0.0});
    return cases;
}

TEST(GuidedCdf, EveryDrawIsTheBinarySearchOfTheCdf) {
    util::Pcg32 rng(11);
    for (const std::vector<double>& w : hardWeights()) {
        const int n = int(w.size());
        std::vector<double> cdf;
        std::vector<uint32_t> guide;
        appendGuidedCdf(w.data(), n, cdf, guide);
        ASSERT_EQ(cdf.size(), size_t(n + 1));
        ASSERT_EQ(guide.size(), size_t(n));
        EXPECT_EQ(cdf.back(), 1.0);
        for (int k = 0; k < 20000; ++k) {
            const double u0 = k < 3 ? std::vector<double>{0.0, 0x1.fffffffffffffp-1, 0.5}[size_t(k)] : rng.nextDouble();
            double u = u0;
            const int got = pickGuidedCdf(cdf.data(), guide.data(), n, u);
            const int want = bruteForce(w, u0);
            // The CDF is normalised in double: at an entry boundary the two may round apart.
            if (got != want) {
                EXPECT_NEAR(u0, cdf[size_t(std::max(got, want))], 1e-12) << n << " " << u0;
            }
            EXPECT_GT(w[size_t(got)], 0.0);
            EXPECT_GE(u, 0.0);
            EXPECT_LT(u, 1.0);
        }
    }
}

TEST(GuidedCdf, AllZeroWeightsAreUniform) {
    const std::vector<double> w(5, 0.0);
    std::vector<double> cdf;
    std::vector<uint32_t> guide;
    appendGuidedCdf(w.data(), 5, cdf, guide);
    for (int i = 0; i < 5; ++i) {
        double u = (i + 0.5) / 5.0;
        EXPECT_EQ(pickGuidedCdf(cdf.data(), guide.data(), 5, u), i);
        EXPECT_NEAR(u, 0.5, 1e-12);
    }
}

// Inverse CDF: N evenly spread u's put floor or ceil of N p_i on entry i, and the rescaled u
// increases with u inside an entry. An alias table over the same weights does not (its counts
// are those of a scattered slot pattern): this is what stratified passes rely on.
TEST(GuidedCdf, EvenlySpreadUDrawEachEntryItsShareWithinOne) {
    for (const std::vector<double>& w : hardWeights()) {
        const int n = int(w.size());
        std::vector<double> cdf;
        std::vector<uint32_t> guide;
        appendGuidedCdf(w.data(), n, cdf, guide);
        double total = 0.0;
        for (double x : w) total += x;
        for (int count : {16, 64, 1000}) {
            std::vector<int> hits(size_t(n), 0);
            std::vector<double> lastU(size_t(n), -1.0);
            for (int k = 0; k < count; ++k) {
                double u = (k + 0.5) / count;
                const int i = pickGuidedCdf(cdf.data(), guide.data(), n, u);
                ++hits[size_t(i)];
                EXPECT_GT(u, lastU[size_t(i)]);
                lastU[size_t(i)] = u;
            }
            for (int i = 0; i < n; ++i)
                EXPECT_LE(std::abs(hits[size_t(i)] - count * w[size_t(i)] / total), 1.0 + 1e-9)
                    << "entry " << i << " of " << n << ", " << count << " draws";
        }
    }
}

} // namespace
} // namespace wavelit::render
