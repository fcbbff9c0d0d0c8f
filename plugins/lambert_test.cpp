// Closed forms of the Lambert plugin: f = ρ/π, pdf = cosθ/π and, because sampling is exactly
// proportional to f·cos, every sample's weight f·cos/pdf equals ρ (zero variance).
#include "plugins/brdf.h"
#include "plugins/testing/brdf_albedo.h"

#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace wavelit::plugins {
namespace {

constexpr float kInvPi = 0.31830988618379067154f;
// Float rounding of a few multiplications.
constexpr float kFloatTolerance = 1e-6f;

TEST(Lambert, EvalIsAlbedoOverPi) {
    const Brdf& b = *findBrdf("lambert");
    BrdfParams p{glm::vec3(0.2f, 0.5f, 0.9f), 0.3f};
    glm::vec3 f = b.eval(p, glm::normalize(glm::vec3(0.3f, 0.2f, 0.9f)),
                         glm::normalize(glm::vec3(-0.5f, 0.1f, 0.2f)));
    EXPECT_NEAR(f.x, 0.2f * kInvPi, kFloatTolerance);
    EXPECT_NEAR(f.y, 0.5f * kInvPi, kFloatTolerance);
    EXPECT_NEAR(f.z, 0.9f * kInvPi, kFloatTolerance);
}

TEST(Lambert, EverySampleWeighsAlbedo) {
    const Brdf& b = *findBrdf("lambert");
    BrdfParams p{glm::vec3(0.2f, 0.5f, 0.9f), 0.3f};
    glm::vec3 wo = glm::normalize(glm::vec3(0.1f, -0.4f, 0.5f));
    util::Pcg32 rng(3);
    for (int i = 0; i < 10000; ++i) {
        BrdfSample s = b.sample(p, wo, rng.nextFloat(), rng.nextFloat());
        if (!s.valid) continue;
        glm::vec3 w = s.f * s.wi.z / s.pdf;
        // Relative: cosθ/pdf·(1/π) cancels up to rounding of cos and 1/π.
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(w[c], p.baseColor[c], 1e-5f);
        ASSERT_NEAR(s.pdf, s.wi.z * kInvPi, kFloatTolerance);
    }
}

TEST(Lambert, QuadratureAlbedoIsBaseColorAtEveryAngle) {
    const Brdf& b = *findBrdf("lambert");
    BrdfParams p{glm::vec3(0.7f), 0.0f};
    for (float deg : {0.0f, 40.0f, 80.0f, 89.5f}) {
        float t = glm::radians(deg);
        glm::dvec3 e = directionalAlbedo(b, p, glm::vec3(std::sin(t), 0.0f, std::cos(t)));
        // Quadrature error bound (1e-4 relative) from plugins/brdf_test.cpp QuadratureIsConverged.
        EXPECT_NEAR(e.x, 0.7, 0.7e-4) << deg;
    }
}

} // namespace
} // namespace wavelit::plugins
