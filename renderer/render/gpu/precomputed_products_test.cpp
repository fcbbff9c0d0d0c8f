// The precomputed axis-bin product pyramids (precomputed_products.h) against closed forms and an
// independent estimate: a Lambert lobe under a constant sky integrates to its albedo, a GGX lobe
// to its directional albedo at normal incidence (the plugin's own importance sampling); a sun's
// mass sits in the leaf that holds the sun, weighted by the axis's cosine, and is 0 behind it;
// every inner cell is the float sum of its four children (what the shader's descent divides).
#include "render/gpu/precomputed_products.h"

#include "render/testing/sampler_test_envs.h"
#include "util/image.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <numbers>

namespace wavelit::render {
namespace {

constexpr int kLevel = 4; // the GPU's product level
constexpr int kLeafOffset = ((1 << (2 * kLevel)) - 1) / 3;

SamplerMaterial material(const char* brdf, float albedo, float roughness) {
    return {brdf, plugins::findBrdf(brdf), {glm::vec3(albedo), roughness}};
}

scene::Environment constantSky(float radiance) {
    scene::Environment env;
    env.image = std::make_shared<util::ImageRGB>(64, 32, glm::vec3(radiance));
    return env;
}

// The integral over the sphere of what the pyramid's root holds (its mean x 4 pi).
double integralOf(const std::vector<float>& p) {
    return double(p[0]) / double(1 << (2 * kLevel)) * 4.0 * std::numbers::pi;
}

TEST(PrecomputedProducts, LambertUnderAConstantSkyIntegratesToTheAlbedo) {
    const SamplerEnvironment env = SamplerEnvironment::build(constantSky(2.0f));
    // L x albedo = 1.2; the 32^2 sub-cell quadrature of the cosine: ~1%.
    for (const glm::dvec3& axis : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, -2, 0.5))})
        EXPECT_NEAR(integralOf(buildBinPyramid(env, material("lambert", 0.6f, 0.5f), kLevel,
                                               {axis, ProductWindow{}})),
                    1.2, 0.02);
}

TEST(PrecomputedProducts, GgxUnderAConstantSkyIntegratesToItsNormalIncidenceAlbedo) {
    const SamplerEnvironment env = SamplerEnvironment::build(constantSky(1.0f));
    const SamplerMaterial ggx = material("ggx", 0.9f, 0.6f);
    // The albedo by the plugin's importance sampling (stratified, 256^2 draws).
    double albedo = 0.0;
    const int n = 256;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const plugins::BrdfSample s = ggx.brdf->sample(ggx.params, glm::vec3(0, 0, 1),
                                                           (i + 0.5f) / n, (j + 0.5f) / n);
            if (s.valid && s.pdf > 0.0f)
                albedo += double(util::luminance(s.f)) * s.wi.z / s.pdf;
        }
    albedo /= n * n;
    EXPECT_NEAR(integralOf(buildBinPyramid(env, ggx, kLevel, {glm::dvec3(0, 1, 0), ProductWindow{}})),
                albedo, 0.03 * albedo);
}

TEST(PrecomputedProducts, InnerCellsAreTheFloatSumsOfTheirChildren) {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, -0.2f));
    const SamplerEnvironment env = SamplerEnvironment::build(makeSunSkyEnvironment(128, sun, 1e6));
    for (const glm::dvec3& axis : {glm::dvec3(sun), glm::dvec3(0, -1, 0)}) {
        const std::vector<float> p =
            buildBinPyramid(env, material("lambert", 0.8f, 0.5f), kLevel, {axis, ProductWindow{}});
        for (int l = 0; l < kLevel; ++l) {
            const int side = 1 << l, off = ((1 << (2 * l)) - 1) / 3,
                      offC = ((1 << (2 * (l + 1))) - 1) / 3;
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    const int c0 = offC + 2 * y * (2 * side) + 2 * x, c1 = c0 + 2 * side;
                    EXPECT_EQ(p[size_t(off + y * side + x)],
                              p[size_t(c0)] + p[size_t(c0 + 1)] + p[size_t(c1)] + p[size_t(c1 + 1)]);
                }
        }
    }
}

TEST(PrecomputedProducts, ASunsMassFollowsTheAxisCosineAndVanishesBehindIt) {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, -0.2f));
    const SamplerEnvironment env = SamplerEnvironment::build(makeSunSkyEnvironment(128, sun, 1e6));
    const SamplerMaterial lambert = material("lambert", 1.0f, 0.5f);
    const glm::dvec3 s(sun);
    auto pyramidAbout = [&](const glm::dvec3& axis) {
        return buildBinPyramid(env, lambert, kLevel, {axis, ProductWindow{}});
    };
    const glm::dvec2 q = env.map().toSquare(s).uv;
    const int side = 1 << kLevel;
    const size_t sunLeaf = size_t(kLeafOffset + std::min(int(q.y * side), side - 1) * side +
                                  std::min(int(q.x * side), side - 1));
    // Facing the sun: its leaf holds most of the mass (1e6 x the sky's mean; the conservative
    // map may spill a little into a neighbour).
    const std::vector<float> facing = pyramidAbout(s);
    EXPECT_GT(facing[sunLeaf], 0.5f * facing[0]);
    // Facing away: nothing from the sun's leaf, and only the dim ground.
    const std::vector<float> away = pyramidAbout(-s);
    EXPECT_EQ(away[sunLeaf], 0.0f);
    EXPECT_LT(away[0], 1e-2f * facing[0]);
    // At 60 degrees from the sun its leaf scales with the cosine, within the sub-cell offsets.
    const glm::dvec3 tilted = glm::normalize(
        0.5 * s + std::sqrt(0.75) * glm::normalize(glm::cross(s, glm::dvec3(0, 0, 1))));
    EXPECT_NEAR(pyramidAbout(tilted)[sunLeaf] / facing[sunLeaf], 0.5, 0.05);
}

} // namespace
} // namespace wavelit::render
