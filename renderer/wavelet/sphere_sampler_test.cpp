#include "wavelet/sphere_sampler.h"
#include "wavelet/tabulate.h"
#include "wavelet/test_support.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace wavelit::wavelet {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kStandardErrors = 3.0;
// A direction re-mapped through toSquare lands in the same texel (see cap_map_test).
constexpr double kPdfConsistency = 1e-9;
// Brute-force reference: a 512^2 equal-area tabulation with 2x2 supersampling, whose own error
// for the smooth sky plus a ~3 degree sun is far below this.
constexpr double kReferenceTolerance = 1e-3;

const glm::dvec3 kSun = glm::normalize(glm::dvec3(0.5, 0.6, -0.3));

double radiance(glm::dvec3 d) {
    return 0.3 + 0.7 * std::max(0.0, d.y) +
           200.0 * std::pow(std::max(0.0, glm::dot(d, kSun)), 800.0);
}

std::vector<SquareGrid> tabulateFaces(const SphereMap& map, int n) {
    std::vector<SquareGrid> faces;
    for (int f = 0; f < map.faceCount(); ++f)
        faces.push_back(tabulate(
            n, [&](glm::dvec2 uv) { return radiance(map.toDirection(f, uv)); }, 4));
    return faces;
}

// Integral of radiance over the sphere estimated with the sampler; returns the per-sample variance.
double expectUnbiased(const SphereMap& map, int n, const char* name) {
    static const double reference = [] {
        OctahedralMap oct;
        return tabulate(
                   9, [&](glm::dvec2 uv) { return radiance(oct.toDirection(0, uv)); }, 2)
                   .integral() *
               4.0 * kPi;
    }();
    auto sampler = SphereSampler::build(map, tabulateFaces(map, n));
    EXPECT_TRUE(sampler.ok());
    util::Pcg32 rng(71);
    const int count = 200000;
    double sum = 0.0, sum2 = 0.0, mismatch = 0.0;
    for (int i = 0; i < count; ++i) {
        const DirectionSample s = sampler->sample({rng.nextDouble(), rng.nextDouble()});
        const double w = radiance(s.direction) / s.pdf;
        sum += w;
        sum2 += w * w;
        mismatch = std::max(mismatch, std::abs(sampler->pdf(s.direction) - s.pdf) / s.pdf);
    }
    const double mean = sum / count, variance = sum2 / count - mean * mean;
    EXPECT_NEAR(mean, reference,
                kStandardErrors * std::sqrt(variance / count) + kReferenceTolerance * reference)
        << name;
    EXPECT_LT(mismatch, kPdfConsistency) << name;
    std::printf("%s: integral %.6g (reference %.6g), relative variance per sample %.4g\n", name,
                mean, reference, variance / (reference * reference));
    return variance;
}

TEST(SphereSampler, OctahedralAndCubeAreUnbiasedWithExactSolidAnglePdf) {
    // Comparable budgets: 64^2 = 4096 octahedral texels vs 6 x 32^2 = 6144 cube texels.
    const double octahedral = expectUnbiased(OctahedralMap(), 6, "octahedral 64^2");
    const double cube = expectUnbiased(CubeMap(), 5, "cube 6 x 32^2");
    EXPECT_GT(octahedral, 0.0);
    EXPECT_GT(cube, 0.0);
}

TEST(SphereSampler, ZeroFacesAreSkippedAndAllZeroIsAnError) {
    CubeMap cube;
    std::vector<SquareGrid> faces(6, SquareGrid(3, 0.0));
    EXPECT_FALSE(SphereSampler::build(cube, faces).ok());
    faces[4] = SquareGrid(3, 1.0); // only +Z
    auto s = SphereSampler::build(cube, faces);
    ASSERT_TRUE(s.ok());
    util::Pcg32 rng(72);
    for (int i = 0; i < 1000; ++i) {
        const DirectionSample d = s->sample({rng.nextDouble(), rng.nextDouble()});
        EXPECT_EQ(cube.toSquare(d.direction).face, 4);
    }
    EXPECT_EQ(s->pdf({0.0, 0.0, -1.0}), 0.0);
}

} // namespace
} // namespace wavelit::wavelet
