#include "wavelet/sphere_map.h"
#include "wavelet/test_support.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace wavelit::wavelet {
namespace {

constexpr double kPi = std::numbers::pi;
// Forward/inverse maps use trig and sqrt in double: ~1e-15 per step; 1e-9 allows for the
// conditioning near the octahedron's folds.
constexpr double kRoundTripTolerance = 1e-9;
// Texel solid angles summed over the sphere: 4 pi up to double rounding.
constexpr double kSolidAngleTolerance = 1e-12;
// Finite-difference Jacobian with step 1e-5: truncation error O(h) ~ 1e-5 relative.
constexpr double kJacobianTolerance = 1e-4;

glm::dvec3 randomDirection(util::Pcg32& rng) {
    const double z = 1.0 - 2.0 * rng.nextDouble(), phi = 2.0 * kPi * rng.nextDouble();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), z, r * std::sin(phi)};
}

void expectMapBasics(const SphereMap& map) {
    util::Pcg32 rng(51);
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 d = randomDirection(rng);
        const FacePoint p = map.toSquare(d);
        const glm::dvec3 back = map.toDirection(p.face, p.uv);
        EXPECT_NEAR(glm::length(back - d), 0.0, kRoundTripTolerance);
        EXPECT_NEAR(glm::length(back), 1.0, kRoundTripTolerance);
    }
    // Jacobian = |d(dir)/du x d(dir)/dv| by central differences at random interior points.
    const double h = 1e-5;
    for (int i = 0; i < 2000; ++i) {
        const int face = int(rng.nextUint() % uint32_t(map.faceCount()));
        const glm::dvec2 uv(0.01 + 0.98 * rng.nextDouble(), 0.01 + 0.98 * rng.nextDouble());
        // Skip the octahedral map's folds (|u'| + |v'| = 1 and the axes), where it is not smooth.
        const double a = std::abs(2 * uv.x - 1), b = std::abs(2 * uv.y - 1);
        if (std::abs(a + b - 1.0) < 4 * h || a < 4 * h || b < 4 * h)
            continue;
        const glm::dvec3 du = (map.toDirection(face, uv + glm::dvec2(h, 0)) -
                               map.toDirection(face, uv - glm::dvec2(h, 0))) /
                              (2 * h);
        const glm::dvec3 dv = (map.toDirection(face, uv + glm::dvec2(0, h)) -
                               map.toDirection(face, uv - glm::dvec2(0, h))) /
                              (2 * h);
        const double j = glm::length(glm::cross(du, dv));
        EXPECT_NEAR(j, map.jacobian(face, uv), kJacobianTolerance * j);
    }
    for (int n : {0, 3, 6}) {
        double total = 0.0;
        for (int f = 0; f < map.faceCount(); ++f)
            for (int y = 0; y < (1 << n); ++y)
                for (int x = 0; x < (1 << n); ++x)
                    total += map.texelSolidAngle(f, n, x, y);
        EXPECT_NEAR(total, 4.0 * kPi, kSolidAngleTolerance);
    }
}

TEST(SphereMap, OctahedralRoundTripJacobianAndArea) {
    expectMapBasics(OctahedralMap());
}
TEST(SphereMap, CubeRoundTripJacobianAndArea) {
    expectMapBasics(CubeMap());
}

TEST(SphereMap, OctahedralIsEqualAreaByChiSquare) {
    // Uniform directions must land uniformly on the square's texels.
    OctahedralMap map;
    util::Pcg32 rng(52);
    const int n = 4, side = 1 << n, count = 200000;
    std::vector<double> observed(size_t(side) * side, 0.0),
        expected(observed.size(), double(count) / (side * side));
    for (int i = 0; i < count; ++i) {
        const FacePoint p = map.toSquare(randomDirection(rng));
        observed[size_t(std::min(int(p.uv.y * side), side - 1)) * side +
                 size_t(std::min(int(p.uv.x * side), side - 1))] += 1;
    }
    EXPECT_GT(util::chiSquareTest(observed, expected).pValue, 0.01);
}

TEST(SphereMap, OctahedralPolesFollowTheYUpConvention) {
    OctahedralMap map;
    EXPECT_NEAR(glm::length(map.toDirection(0, {0.5, 0.5}) - glm::dvec3(0, 1, 0)), 0.0,
                kRoundTripTolerance);
    EXPECT_NEAR(glm::length(map.toDirection(0, {0.0, 0.0}) - glm::dvec3(0, -1, 0)), 0.0,
                kRoundTripTolerance);
    CubeMap cube;
    EXPECT_EQ(cube.toSquare({0, 1, 0}).face, 2);
    EXPECT_EQ(cube.toSquare({0, 0, -3}).face, 5);
}

} // namespace
} // namespace wavelit::wavelet
