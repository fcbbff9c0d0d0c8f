#include "wavelet/cap_map.h"
#include "wavelet/product.h"
#include "wavelet/tabulate.h"
#include "wavelet/test_support.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace wavelit::wavelet {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRoundTripTolerance = 1e-9; // double trig, see sphere_map_test
constexpr double kChiSquareAlpha = 0.01;
constexpr double kStandardErrors = 3.0;
// pdf(sample.direction) vs the returned pdf: the direction is mapped back to the square with
// ~1e-15 error, so it lands in the same leaf and the pdf matches to double rounding.
constexpr double kPdfConsistency = 1e-9;

TEST(CapMap, ConcentricDiskRoundTrip) {
    util::Pcg32 rng(61);
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec2 uv(rng.nextDouble(), rng.nextDouble());
        const glm::dvec2 back = diskToSquare(squareToDisk(uv));
        EXPECT_NEAR(back.x, uv.x, kRoundTripTolerance);
        EXPECT_NEAR(back.y, uv.y, kRoundTripTolerance);
    }
}

TEST(CapMap, RoundTripStaysInsideAndIsEqualArea) {
    util::Pcg32 rng(62);
    for (double angle : {0.01, 0.3, 1.2, kPi}) {
        CapMap cap(glm::dvec3(0.3, 0.8, -0.5), angle);
        EXPECT_NEAR(cap.solidAngle(), 2.0 * kPi * (1.0 - std::cos(angle)), 1e-12);
        for (int i = 0; i < 5000; ++i) {
            const glm::dvec2 uv(rng.nextDouble(), rng.nextDouble());
            const glm::dvec3 d = cap.toDirection(uv);
            EXPECT_NEAR(glm::length(d), 1.0, kRoundTripTolerance);
            EXPECT_GE(glm::dot(d, cap.axis()), std::cos(angle) - kRoundTripTolerance);
            auto back = cap.toSquare(d);
            ASSERT_TRUE(back.has_value());
            EXPECT_NEAR(back->x, uv.x, kRoundTripTolerance * 100 / angle);
            EXPECT_NEAR(back->y, uv.y, kRoundTripTolerance * 100 / angle);
        }
        if (angle < kPi) {
            EXPECT_FALSE(cap.toSquare(-cap.axis()).has_value());
        }
        // Equal area: uniform directions inside the cap land uniformly on 8 x 8 texels.
        const int side = 8, count = 100000;
        std::vector<double> observed(side * side, 0.0),
            expected(side * side, double(count) / (side * side));
        for (int i = 0; i < count; ++i) {
            // Uniform in the cap: cos theta uniform in [cos max, 1].
            const double c = 1.0 - rng.nextDouble() * (1.0 - std::cos(angle)),
                         phi = 2 * kPi * rng.nextDouble();
            const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
            const glm::dvec2 local(s * std::cos(phi), s * std::sin(phi));
            // Any frame around the axis will do: uniform in a cap is invariant under rotation.
            const glm::dvec3 t = glm::normalize(glm::cross(cap.axis(), glm::dvec3(1.0, 0.0, 0.0)));
            const glm::dvec3 b = glm::cross(cap.axis(), t);
            const glm::dvec3 d = local.x * t + local.y * b + c * cap.axis();
            auto uv = cap.toSquare(d);
            ASSERT_TRUE(uv.has_value());
            observed[size_t(std::min(int(uv->y * side), side - 1)) * side +
                     size_t(std::min(int(uv->x * side), side - 1))] += 1;
        }
        EXPECT_GT(util::chiSquareTest(observed, expected).pValue, kChiSquareAlpha) << angle;
    }
}

TEST(CapMap, LobeWidthChoosesTheCap) {
    EXPECT_NEAR(capHalfAngleForLobe(0.1), 0.3, 1e-15);
    EXPECT_NEAR(capHalfAngleForLobe(2.0), kPi, 1e-15);
}

TEST(CapSampler, ProductOverACapIsUnbiasedWithExactSolidAnglePdf) {
    // A narrow lobe (half-width ~0.05 rad) around an axis times a bright spot inside it: tabulated
    // on a 64^2 cap of 3 lobe widths, sampled, and the solid-angle estimator checked against a
    // brute-force integral over the cap.
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, 1.0, 0.1));
    const double width = 0.05;
    CapMap cap(axis, capHalfAngleForLobe(width));
    const glm::dvec3 spot = cap.toDirection({0.6, 0.45});
    auto lobeF = [&](glm::dvec3 d) {
        const double a = std::acos(std::clamp(glm::dot(d, axis), -1.0, 1.0));
        return std::exp(-a * a / (2 * width * width));
    };
    auto lightF = [&](glm::dvec3 d) {
        return 0.2 + 50.0 * std::pow(std::max(0.0, glm::dot(d, spot)), 20000.0);
    };
    const int n = 6;
    SquareGrid lobeGrid = tabulate(n, [&](glm::dvec2 uv) { return lobeF(cap.toDirection(uv)); });
    SquareGrid lightGrid = tabulate(n, [&](glm::dvec2 uv) { return lightF(cap.toDirection(uv)); });
    SparseHaar a = sparsify(forwardHaar(lobeGrid)), b = sparsify(forwardHaar(lightGrid));
    const SparseHaar* list[] = {&a, &b};
    ScalingTree product = sparseProduct(list);
    auto square = HierarchicalSampler::build(product);
    ASSERT_TRUE(square.ok());

    // Chi-square in the cap's square against the tabulated product.
    const std::vector<double> expected = testing::clampedCellProbabilities(product.toGrid(), n);
    EXPECT_GT(testing::chiSquare(*square, expected, n, 200000, 64).pValue, kChiSquareAlpha);

    CapSampler sampler(cap, *square);
    // Brute-force integral over the cap (solid angle): equal-area, so the square mean x area.
    const SquareGrid fine = tabulate(
        9, [&](glm::dvec2 uv) { return lobeF(cap.toDirection(uv)) * lightF(cap.toDirection(uv)); },
        2);
    const double integral = fine.integral() * cap.solidAngle();
    util::Pcg32 rng(64);
    const int count = 200000;
    double sum = 0.0, sum2 = 0.0, mismatch = 0.0;
    for (int i = 0; i < count; ++i) {
        const DirectionSample s = sampler.sample({rng.nextDouble(), rng.nextDouble()});
        const double w = lobeF(s.direction) * lightF(s.direction) / s.pdf;
        sum += w;
        sum2 += w * w;
        mismatch = std::max(mismatch, std::abs(sampler.pdf(s.direction) - s.pdf) / s.pdf);
    }
    const double mean = sum / count, se = std::sqrt((sum2 / count - mean * mean) / count);
    // The brute-force reference itself has tabulation error; allow 3 se plus 0.1% for it.
    EXPECT_NEAR(mean, integral, kStandardErrors * se + 1e-3 * integral);
    // pdf(direction) goes back through toSquare; round-off there could move a point across a
    // texel border, which would show as a mismatch far above this bound.
    EXPECT_LT(mismatch, kPdfConsistency);
    EXPECT_EQ(sampler.pdf(-axis), 0.0);
}

} // namespace
} // namespace wavelit::wavelet
