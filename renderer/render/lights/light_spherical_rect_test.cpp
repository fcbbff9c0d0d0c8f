// Spherical-rectangle sampling (Ureña et al. 2013): its solid angle against the closed form of a
// rectangle seen from a point above one corner (combined with signs for any foot point), and its
// samples landing on the rectangle. The distribution itself is checked by the rect light's
// chi-square in light_sampler_test.cpp.
#include "render/lights/light_spherical_rect.h"

#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace wavelit::render {
namespace {

// Float: the four angles are acos of float dot products (~1e-7 absolute each, summed; worse
// near a hemisphere, where the angles approach π and acos is ill-conditioned): 2e-6 + 4e-6 S.
constexpr double kSolidAngleAbsolute = 2e-6, kSolidAngleRelative = 4e-6;
// Sample points: float rounding of the paper's mapping, relative to the rectangle's size.
constexpr float kOnRectTolerance = 1e-4f;

// Solid angle of [0,a]×[0,b] at height h above the origin: asin(ab / sqrt((a²+h²)(b²+h²))),
// odd in a and b so that signed corners combine (as form factors do).
double cornerSolidAngle(double a, double b, double h) {
    return std::asin(a * b / std::sqrt((a * a + h * h) * (b * b + h * h)));
}

double rectSolidAngle(double x0, double x1, double y0, double y1, double h) {
    return cornerSolidAngle(x1, y1, h) - cornerSolidAngle(x0, y1, h) -
           cornerSolidAngle(x1, y0, h) + cornerSolidAngle(x0, y0, h);
}

TEST(SphericalRect, SolidAngleMatchesTheClosedForm) {
    const glm::vec3 corner(-0.5f, 1.0f, -0.25f), ex(1.0f, 0.0f, 0.0f), ey(0.0f, 0.0f, 0.5f);
    for (glm::vec3 o : {glm::vec3(0.0f), glm::vec3(0.3f, 0.2f, -0.1f), glm::vec3(2.0f, 0.0f, 1.0f),
                        glm::vec3(0.0f, 0.99f, 0.0f), glm::vec3(0.0f, 3.0f, 0.0f)}) {
        SphericalRect sr(corner, ex, ey, o);
        const double h = std::abs(double(corner.y) - o.y);
        const double expected = rectSolidAngle(corner.x - o.x, corner.x + 1.0 - o.x,
                                               corner.z - o.z, corner.z + 0.5 - o.z, h);
        EXPECT_NEAR(sr.solidAngle(), expected, kSolidAngleAbsolute + kSolidAngleRelative * expected)
            << o.x << "," << o.y << "," << o.z;
    }
}

TEST(SphericalRect, SamplesLandOnTheRectangle) {
    const glm::vec3 corner(-0.5f, 1.0f, -0.25f), ex(1.0f, 0.0f, 0.0f), ey(0.0f, 0.0f, 0.5f);
    util::Pcg32 rng(2);
    for (glm::vec3 o : {glm::vec3(0.0f), glm::vec3(1.5f, 0.9f, 0.0f), glm::vec3(0.0f, 1.5f, 0.0f)}) {
        SphericalRect sr(corner, ex, ey, o);
        for (int i = 0; i < 1000; ++i) {
            const float u1 = rng.nextFloat();
            const float u2 = rng.nextFloat();
            const glm::vec3 q = sr.samplePoint({u1, u2}) - corner;
            ASSERT_NEAR(q.y, 0.0f, kOnRectTolerance);
            ASSERT_GE(q.x, -kOnRectTolerance);
            ASSERT_LE(q.x, 1.0f + kOnRectTolerance);
            ASSERT_GE(q.z, -kOnRectTolerance);
            ASSERT_LE(q.z, 0.5f + kOnRectTolerance);
        }
    }
}

} // namespace
} // namespace wavelit::render
