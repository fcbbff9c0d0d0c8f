// Product tables and windows (issue 6): the policy per material, windows that contain their
// caps and align with the global quadtree, the flat GPU export round-tripping, and the refined
// product sampler's pdf agreeing with what it draws.
#include "render/sampling/product/env_product_tables.h"

#include "plugins/brdf_table.h"
#include "render/sampling/product/env_product_sampler.h"
#include "render/testing/sampler_test_envs.h"
#include "render/sampling/sampler_window.h"
#include "util/rng.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace wavelit::render {
namespace {

// Relative agreement of the pdf a draw returns with pdf(direction) in double: the only
// difference is the direction -> square round trip (1e-16), except on texel edges.
constexpr double kPdfRelativeTolerance = 1e-9;

SamplerEnvironment sunEnvironment() {
    return SamplerEnvironment::build(
        makeSunSkyEnvironment(256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e6));
}

TEST(EnvProductTables, PolicyFollowsLobeWidth) {
    const SamplerEnvironment env = sunEnvironment();
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    const plugins::Brdf* lambert = plugins::findBrdf("lambert");
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.02f}, env).mode, ProductMode::BsdfLobe);
    const ProductPolicy glossy = chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.3f}, env);
    EXPECT_EQ(glossy.mode, ProductMode::Product);
    EXPECT_GT(glossy.binLevel, 0);
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 1.0f}, env).binLevel, 0);
    EXPECT_TRUE(chooseProductPolicy(*lambert, {glm::vec3(0.8f), 0.5f}, env).aroundNormal);
    scene::Environment black;
    black.image = std::make_shared<util::ImageRGB>(32, 16, glm::vec3(0.0f));
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.5f}, SamplerEnvironment::build(black)).mode,
              ProductMode::BsdfLobe);
}

// Mirror lobes by their width in env texels (texel = sqrt(4 pi) 2^-level, the octahedral map's):
// under 2 texels BsdfLobe, from 2 to 4 EnvMis (the product resolves the lobe no better than mis's
// technique: glossy_sun's chrome, docs/performance.md "Sun-lit fireflies of the wavelet sampler"),
// from 4 the product. ggx's half-width is 2 r^2; a 512 x 256 sun map has level 9 like the city
// map (texel 0.00692 rad), where the city's chrome (r = 0.1: 2.9 texels) takes mis's technique
// and r = 0.2 (11.6 texels) keeps its product.
TEST(EnvProductTables, MirrorLobesOfTwoToFourEnvTexelsTakeMisTechnique) {
    const SamplerEnvironment env = SamplerEnvironment::build(
        makeSunSkyEnvironment(512, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e6));
    ASSERT_EQ(env.level(), 9);
    const double texel = std::sqrt(4.0 * 3.141592653589793) / 512.0;
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    // The roughness whose half-width is `texels` env texels.
    auto roughness = [&](double texels) { return float(std::sqrt(texels * texel / 2.0)); };
    auto mode = [&](float r) { return chooseProductPolicy(*ggx, {glm::vec3(0.9f), r}, env).mode; };
    EXPECT_EQ(mode(roughness(1.95)), ProductMode::BsdfLobe);
    EXPECT_EQ(mode(roughness(2.05)), ProductMode::EnvMis);
    EXPECT_EQ(mode(0.1f), ProductMode::EnvMis);
    EXPECT_EQ(mode(roughness(3.95)), ProductMode::EnvMis);
    EXPECT_EQ(mode(roughness(4.05)), ProductMode::Product);
    EXPECT_EQ(mode(0.2f), ProductMode::Product);
    const ProductPolicy chrome = chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.1f}, env);
    EXPECT_NE(chrome.reason.find("4 env texels"), std::string::npos) << chrome.reason;
    EXPECT_EQ(MaterialProductTables::build(env, chrome).bytes(), 0u);
    // A constant env (level 4, texels 0.22 rad that are no detail of its light) is exempt: a lobe
    // of 3 such texels (ggx r = 0.58, a 1.34 sr lobe within 16x of the env's 4 pi) keeps its product.
    scene::Environment flat;
    flat.image = std::make_shared<util::ImageRGB>(8, 4, glm::vec3(1.0f));
    const SamplerEnvironment constant = SamplerEnvironment::build(flat);
    ASSERT_EQ(constant.level(), 4);
    const float r3 = float(std::sqrt(3.0 * std::sqrt(4.0 * 3.141592653589793) / 16.0 / 2.0));
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), r3}, constant).mode, ProductMode::Product);
}

// The extents rule (kEnvMisSolidAngleRatio), for mirror lobes: the product only where env and
// lobe are of comparable extent. A constant env spreads over 4 pi sr: a narrow mirror lobe is
// left to BSDF sampling (EnvMis). A sun holding the light: the mirror lobe keeps its product.
TEST(EnvProductTables, MirrorLobeProductOnlyWhereEnvAndLobeHaveComparableExtent) {
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    scene::Environment flat;
    flat.image = std::make_shared<util::ImageRGB>(512, 256, glm::vec3(1.0f)); // texels << the lobe
    const SamplerEnvironment constant = SamplerEnvironment::build(flat);
    EXPECT_NEAR(constant.effectiveSolidAngle(), 4.0 * 3.141592653589793, 1e-9);
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, constant).mode, ProductMode::EnvMis);
    const SamplerEnvironment sun = sunEnvironment();
    EXPECT_LT(sun.effectiveSolidAngle(), 0.05);
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, sun).mode, ProductMode::Product);
}

// A hemisphere-wide lobe about the normal (Lambert) takes `mis`'s technique under every lit env
// (docs/performance.md "Equal time, round 5": its product did not pay for its pass): under a
// constant env, where the extents rule alone would have kept the product (4 pi sr vs the
// cosine's 1.5 pi), and under a sun. No tables are built for it. A glossy lobe about the normal
// (a measured table) keeps its whole-sphere product.
TEST(EnvProductTables, HemisphereWideLobesTakeMisTechniqueUnderEveryEnv) {
    const plugins::Brdf* lambert = plugins::findBrdf("lambert");
    scene::Environment flat;
    flat.image = std::make_shared<util::ImageRGB>(512, 256, glm::vec3(1.0f));
    const SamplerEnvironment constant = SamplerEnvironment::build(flat);
    const SamplerEnvironment sun = sunEnvironment();
    for (const SamplerEnvironment* env : {&constant, &sun}) {
        const ProductPolicy p = chooseProductPolicy(*lambert, {glm::vec3(0.8f), 1.0f}, *env);
        EXPECT_EQ(p.mode, ProductMode::EnvMis);
        EXPECT_TRUE(p.aroundNormal);
        const MaterialProductTables t = MaterialProductTables::build(*env, p);
        EXPECT_EQ(t.factorCount(), 0u);
        EXPECT_EQ(t.bytes(), 0u);
    }
    auto table = plugins::loadMerlBrdf(std::string(WAVELIT_RESOURCE_DIR) +
                                       "/brdfs/glossy-copper-r05.binary");
    ASSERT_TRUE(table.ok()) << table.error().message();
    const ProductPolicy measured = chooseProductPolicy(
        *plugins::findBrdf("measured"), {glm::vec3(1.0f), 0.5f, 0.0f, *table}, constant);
    EXPECT_EQ(measured.mode, ProductMode::Product);
    EXPECT_TRUE(measured.aroundNormal);
    EXPECT_LT(measured.lobeHalfWidth, 0.5 * 3.141592653589793);
}

TEST(SamplerWindow, ContainsItsCapAndAlignsWithTheQuadtree) {
    const wavelet::OctahedralMap map;
    util::Pcg32 rng(3);
    for (int i = 0; i < 200; ++i) {
        const double z = 2.0 * rng.nextDouble() - 1.0, phi = 6.283185307179586 * rng.nextDouble();
        const double s = std::sqrt(1.0 - z * z);
        const glm::dvec3 axis(s * std::cos(phi), z, s * std::sin(phi));
        const double cap = 0.02 + 0.5 * rng.nextDouble();
        const ProductWindow w = chooseWindow(map, axis, cap, 7);
        glm::dvec2 local;
        EXPECT_TRUE(w.toLocal(octSquarePoint(map, axis), local));
        int gl, gx, gy;
        w.globalCell(5, 0, 0, gl, gx, gy);
        EXPECT_DOUBLE_EQ(std::ldexp(double(gx), -gl), w.origin().x);
        EXPECT_DOUBLE_EQ(std::ldexp(double(gy), -gl), w.origin().y);
    }
}

TEST(EnvProductTables, FlatExportRoundTrips) {
    const SamplerEnvironment env = sunEnvironment();
    // r = 0.2: a windowed policy (at r = 0.3 the 4.5-half-width cap is the whole sphere).
    const MaterialProductTables t = MaterialProductTables::build(
        env, chooseProductPolicy(*plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.2f}, env));
    const FlatProductTables flat = t.flatten();
    ASSERT_GT(t.factorCount(), 1u);
    // bytes() counts the export without building it.
    EXPECT_EQ(t.bytes(), 4 * (flat.header.size() + flat.nodeWords.size() + flat.scaling.size()));
    for (int bin = 0; bin < t.binCount(); bin += 97) {
        namespace fl = flat_layout;
        const uint32_t* b = &flat.header[size_t(fl::binWordsAt(bin))];
        EXPECT_EQ(int(b[fl::kBinK]), t.window(bin).k);
        const wavelet::SparseHaar decoded =
            unflattenFactor(flat, int(b[fl::kBinFactor]), t.policy().productLevel);
        const wavelet::SparseHaar& original = t.envFactor(bin);
        ASSERT_EQ(decoded.nodes.size(), original.nodes.size());
        for (size_t n = 0; n < original.nodes.size(); ++n)
            for (int d = 0; d < 3; ++d)
                EXPECT_EQ(decoded.nodes[n].detail[d], double(float(original.nodes[n].detail[d])));
    }
    EXPECT_GT(t.bytes(), 0u);
}

TEST(EnvProductSampler, ReturnedPdfEqualsPdfOfTheDraw) {
    const SamplerEnvironment env = sunEnvironment();
    const ProductPolicy policy =
        chooseProductPolicy(*plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.3f}, env);
    const MaterialProductTables t = MaterialProductTables::build(env, policy);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.25, 0.8, 0.2));
    const int bin = t.binOf(axis);
    const wavelet::SquareGrid lobe = windowTabulate(env.map(), t.window(bin), policy.productLevel,
                                                    [&](const glm::dvec3& d) {
                                                        const double c = glm::dot(d, axis);
                                                        return c > 0.0 ? std::pow(c, 40.0) : 0.0;
                                                    });
    const auto sampler =
        EnvProductSampler::buildSparse(env, t.window(bin), t.envFactor(bin), lobe, policy.brdfKeep);
    ASSERT_TRUE(sampler.has_value());
    util::Pcg32 rng(11);
    int mismatches = 0;
    for (int i = 0; i < 20000; ++i) {
        const double u1 = rng.nextDouble();
        const wavelet::DirectionSample s = sampler->sampleLocal({u1, rng.nextDouble()});
        ASSERT_GT(s.pdf, 0.0);
        if (std::abs(sampler->pdfLocal(s.direction) - s.pdf) > kPdfRelativeTolerance * s.pdf)
            ++mismatches;
    }
    EXPECT_LE(mismatches, 2);
}

} // namespace
} // namespace wavelit::render
