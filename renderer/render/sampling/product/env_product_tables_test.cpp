// Product tables and windows (issue 6): the policy per material, windows that contain their
// caps and align with the global quadtree, the flat GPU export round-tripping, and the refined
// product sampler's pdf agreeing with what it draws.
#include "render/sampling/product/env_product_tables.h"

#include "plugins/brdf_table.h"
#include "render/sampling/product/env_product_sampler.h"
#include "render/sampling/sampler_constants.h"
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

constexpr double kPi = 3.141592653589793;

const glm::vec3 kSunDirection = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));

// A sky whose one-texel sun (10^6 x the sky's mean) holds the light: its effective solid angle
// is about a texel's, far narrower than any lobe the product resolves.
SamplerEnvironment sunEnvironment() {
    return SamplerEnvironment::build(makeSunSkyEnvironment(256, kSunDirection, 1e6));
}

// A sky whose 13-degree sun (10^4 x the sky's mean, ~97% of the light) is a concentrated light of
// the extent of a glossy lobe (effective solid angle 0.047 sr, between the city sun's 0.0048 and
// the studio's 0.078): where the product is still chosen for ggx r = 0.2 (0.020 sr).
SamplerEnvironment wideSunEnvironment() {
    return SamplerEnvironment::build(makeSunSkyEnvironment(512, kSunDirection, 1e4, 13.0));
}

// ggx's half-width is 2 r^2 and a mirror lobe's extent 2 pi (1 - cos half-width): the roughness
// whose lobe spans `solidAngle` sr.
float ggxRoughnessOfSolidAngle(double solidAngle) {
    return float(std::sqrt(std::acos(1.0 - solidAngle / (2.0 * kPi)) / 2.0));
}

TEST(EnvProductTables, PolicyFollowsLobeWidth) {
    const SamplerEnvironment env = wideSunEnvironment();
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    const plugins::Brdf* lambert = plugins::findBrdf("lambert");
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.02f}, env).mode, ProductMode::BsdfLobe);
    const ProductPolicy glossy = chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, env);
    EXPECT_EQ(glossy.mode, ProductMode::Product);
    EXPECT_GT(glossy.binLevel, 0);
    // A whole-sphere lobe (r = 1: 8.9 sr) is of the extent of a constant env (4 pi sr).
    scene::Environment flat;
    flat.image = std::make_shared<util::ImageRGB>(512, 256, glm::vec3(1.0f));
    const ProductPolicy rough =
        chooseProductPolicy(*ggx, {glm::vec3(0.9f), 1.0f}, SamplerEnvironment::build(flat));
    EXPECT_EQ(rough.mode, ProductMode::Product);
    EXPECT_EQ(rough.binLevel, 0);
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
// map (texel 0.00692 rad), where the city's chrome (r = 0.1: 2.9 texels) takes mis's technique.
// The sun is a 4-degree disc holding the light, of about the city sun's effective solid angle
// (0.0048 sr), so a lobe of 4 texels (0.0025 sr) is within the extents rule; r = 0.2 (11.6 texels,
// 0.0201 sr, over 3x the sun) is EnvMis by the lobe-wider side (glossy_r02_sun's glossy sphere).
TEST(EnvProductTables, MirrorLobesOfTwoToFourEnvTexelsTakeMisTechnique) {
    const SamplerEnvironment env =
        SamplerEnvironment::build(makeSunSkyEnvironment(512, kSunDirection, 1e5, 4.0));
    ASSERT_EQ(env.level(), 9);
    ASSERT_GT(env.effectiveSolidAngle(), 0.004);
    ASSERT_LT(env.effectiveSolidAngle(), 0.006);
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
    const ProductPolicy r02 = chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, env);
    EXPECT_EQ(r02.mode, ProductMode::EnvMis);
    EXPECT_NE(r02.reason.find("lobe wider than the env"), std::string::npos) << r02.reason;
    const ProductPolicy chrome = chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.1f}, env);
    EXPECT_NE(chrome.reason.find("4 env texels"), std::string::npos) << chrome.reason;
    EXPECT_EQ(MaterialProductTables::build(env, chrome).bytes(), 0u);
    // A constant env (level 4, texels 0.22 rad that are no detail of its light) is exempt: a lobe
    // of 3.9 such texels (ggx r = 0.66, a 2.2 sr lobe within 6x of the env's 4 pi) keeps its product.
    scene::Environment flat;
    flat.image = std::make_shared<util::ImageRGB>(8, 4, glm::vec3(1.0f));
    const SamplerEnvironment constant = SamplerEnvironment::build(flat);
    ASSERT_EQ(constant.level(), 4);
    const float r39 = float(std::sqrt(3.9 * std::sqrt(4.0 * kPi) / 16.0 / 2.0));
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), r39}, constant).mode, ProductMode::Product);
}

// The extents rule, for mirror lobes: the product only where env and lobe are of comparable
// extent. A constant env spreads over 4 pi sr: a narrow mirror lobe is left to BSDF sampling
// (EnvMis). A one-texel sun holding the light sits inside the lobe: env sampling follows the
// integrand (EnvMis). A sun of the lobe's extent holding the light: the lobe keeps its product.
TEST(EnvProductTables, MirrorLobeProductOnlyWhereEnvAndLobeHaveComparableExtent) {
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    scene::Environment flat;
    flat.image = std::make_shared<util::ImageRGB>(512, 256, glm::vec3(1.0f)); // texels << the lobe
    const SamplerEnvironment constant = SamplerEnvironment::build(flat);
    EXPECT_NEAR(constant.effectiveSolidAngle(), 4.0 * 3.141592653589793, 1e-9);
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, constant).mode, ProductMode::EnvMis);
    // ... but a lobe of 1/8 of it keeps the product: a constant env holds the env-wider side to
    // kUniformEnvMisSolidAngleRatio (16), not 6 (the furnace's ggx r = 0.6).
    const ProductPolicy wide = chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.6f}, constant);
    const double wideLobe = 2.0 * 3.141592653589793 * (1.0 - std::cos(wide.lobeHalfWidth));
    EXPECT_GT(constant.effectiveSolidAngle(), kEnvMisSolidAngleRatio * wideLobe);
    EXPECT_EQ(wide.mode, ProductMode::Product) << wide.reason;
    const SamplerEnvironment sun = sunEnvironment();
    EXPECT_LT(sun.effectiveSolidAngle(), 0.001);
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, sun).mode, ProductMode::EnvMis);
    const SamplerEnvironment wideSun = wideSunEnvironment();
    EXPECT_EQ(chooseProductPolicy(*ggx, {glm::vec3(0.9f), 0.2f}, wideSun).mode,
              ProductMode::Product);
}

// The two-sided extents rule's boundaries (sampler_constants.h): env wider than 6x the lobe
// (kEnvMisSolidAngleRatio) or lobe wider than the env (kLobeMisSolidAngleRatio = 1) take mis's
// technique; between them (env 1-6x the lobe) the product. Lobes sized to straddle each boundary
// by ~2% under the 13-degree sun (every one of them >= 4 env texels wide, so only the extents
// decide), and the reason names the rule that fired with its numbers.
TEST(EnvProductTables, ProductOnlyWhereTheEnvIsOneToSixTimesTheLobe) {
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    const SamplerEnvironment env = wideSunEnvironment();
    const double envOmega = env.effectiveSolidAngle();
    ASSERT_GT(envOmega, 0.03);
    ASSERT_LT(envOmega, 0.06);
    auto policy = [&](double lobeOverEnv) {
        return chooseProductPolicy(
            *ggx, {glm::vec3(0.9f), ggxRoughnessOfSolidAngle(lobeOverEnv * envOmega)}, env);
    };
    const ProductPolicy half = policy(0.5);
    EXPECT_EQ(half.mode, ProductMode::Product);
    EXPECT_NEAR(2.0 * kPi * (1.0 - std::cos(half.lobeHalfWidth)), 0.5 * envOmega, 1e-4 * envOmega);
    EXPECT_NE(half.reason.find("comparable extents"), std::string::npos) << half.reason;
    EXPECT_NE(half.reason.find("(env / lobe 2, within 1..6)"), std::string::npos) << half.reason;

    EXPECT_EQ(policy(1.0 / 5.9).mode, ProductMode::Product);
    const ProductPolicy envWider = policy(1.0 / 6.1);
    EXPECT_EQ(envWider.mode, ProductMode::EnvMis);
    EXPECT_NE(envWider.reason.find("env wider than the lobe"), std::string::npos) << envWider.reason;
    EXPECT_NE(envWider.reason.find("> 6 x the lobe's"), std::string::npos) << envWider.reason;
    EXPECT_NE(envWider.reason.find("(ratio 6.1)"), std::string::npos) << envWider.reason;

    EXPECT_EQ(policy(0.98).mode, ProductMode::Product);
    const ProductPolicy lobeWider = policy(1.02);
    EXPECT_EQ(lobeWider.mode, ProductMode::EnvMis);
    EXPECT_NE(lobeWider.reason.find("lobe wider than the env"), std::string::npos)
        << lobeWider.reason;
    EXPECT_NE(lobeWider.reason.find("> 1 x the env"), std::string::npos) << lobeWider.reason;
    EXPECT_NE(lobeWider.reason.find("(ratio 1.02)"), std::string::npos) << lobeWider.reason;
    // EnvMis materials build no tables.
    EXPECT_EQ(MaterialProductTables::build(env, envWider).bytes(), 0u);
    EXPECT_EQ(MaterialProductTables::build(env, lobeWider).bytes(), 0u);
}

// The rule's decisions on the bundled maps it was measured on (docs/performance.md "Comparable
// extents, two-sided": relRMSE^2 x spp of `mis` vs `wavelet`), effective solid angles of the
// full-resolution maps: studio 0.078 sr (ring_on_ground), courtyard 1.429 sr (cornell_box), city
// 0.0048 sr (the *_sun scenes, its sun).
TEST(EnvProductTables, ComparableExtentsOnTheMeasuredMaps) {
    auto load = [](const char* name) {
        auto e = loadDownsampledEnvironment(std::string(WAVELIT_RESOURCE_DIR) + "/envmaps/" + name,
                                            1 << 16);
        EXPECT_TRUE(e.ok()) << name;
        return SamplerEnvironment::build(e.ok() ? *e : scene::Environment{});
    };
    const SamplerEnvironment studio = load("studio.exr"), courtyard = load("courtyard.exr"),
                             city = load("city.exr");
    EXPECT_NEAR(studio.effectiveSolidAngle(), 0.078, 0.0005);
    EXPECT_NEAR(courtyard.effectiveSolidAngle(), 1.429, 0.0005);
    EXPECT_NEAR(city.effectiveSolidAngle(), 0.004817, 0.000005);
    const plugins::Brdf* ggx = plugins::findBrdf("ggx");
    struct Case {
        const SamplerEnvironment* env;
        float roughness;
        ProductMode mode;
        const char* why; // what the reason starts with
    };
    const Case cases[] = {
        // The gold at r = 0.27: the lobe 0.85x the env, the product wins per sample (~1.5x).
        {&studio, 0.27f, ProductMode::Product, "mirror lobe"},
        // The default scene's gold: env 3.9x the lobe, the product wins per sample (~1.6x).
        {&studio, 0.2f, ProductMode::Product, "mirror lobe"},
        // The gold at r = 0.18: env 5.9x the lobe, the product still wins (~1.4x).
        {&studio, 0.18f, ProductMode::Product, "mirror lobe"},
        // The gold at r = 0.16: env 9.5x the lobe.
        {&studio, 0.16f, ProductMode::EnvMis, "env wider than the lobe"},
        // The gold at r = 0.45: the lobe 6.5x the env, the product wins ~1.25x per sample, less
        // than its pass costs.
        {&studio, 0.45f, ProductMode::EnvMis, "lobe wider than the env"},
        // cornell_box's ggx box (r = 0.35): env 7.6x the lobe, a tie per sample.
        {&courtyard, 0.35f, ProductMode::EnvMis, "env wider than the lobe"},
        // r = 0.15 under the city sun: the lobe 1.3x the sun, the product 1.6-2.4x worse.
        {&city, 0.15f, ProductMode::EnvMis, "lobe wider than the env"},
        // glossy_r02_sun's sphere: the lobe 4.2x the city sun, the product 5% worse per sample.
        {&city, 0.2f, ProductMode::EnvMis, "lobe wider than the env"},
        // r = 0.4 under the city sun: the lobe 66x the sun, the product 32% worse per sample.
        {&city, 0.4f, ProductMode::EnvMis, "lobe wider than the env"},
    };
    for (const Case& c : cases) {
        const ProductPolicy p = chooseProductPolicy(*ggx, {glm::vec3(0.9f), c.roughness}, *c.env);
        EXPECT_EQ(p.mode, c.mode) << "r = " << c.roughness << ": " << p.reason;
        EXPECT_EQ(p.reason.rfind(c.why, 0), 0u) << p.reason;
    }
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
    // Under the 13-degree sun (under the one-texel sun r = 0.2 is EnvMis: no tables).
    const SamplerEnvironment env = wideSunEnvironment();
    // r = 0.2: a windowed policy (at r = 0.3 the 4.5-half-width cap is the whole sphere).
    const ProductPolicy policy =
        chooseProductPolicy(*plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.2f}, env);
    ASSERT_EQ(policy.mode, ProductMode::Product);
    const MaterialProductTables t = MaterialProductTables::build(env, policy);
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
    // The 13-degree sun: r = 0.22 (0.029 sr) keeps its product there (under the one-texel sun it
    // is EnvMis).
    const SamplerEnvironment env = wideSunEnvironment();
    const ProductPolicy policy =
        chooseProductPolicy(*plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.22f}, env);
    ASSERT_EQ(policy.mode, ProductMode::Product);
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

// The tracers' leaves take f at each sub-cell centre bilinearly from the leaf's corners
// (windowTabulateEnvWeightedCornersBatch): exact where f is bilinear in the window's square
// coordinates, so there the grid equals the one from the sub-cell centres themselves, env
// weighting and all (the 13-degree sun weights the sub-cells unevenly). A leaf whose corners all
// see 0 is 0.
TEST(EnvProductSampler, CornerLeavesEqualSubCellCentresWhereFIsBilinear) {
    const SamplerEnvironment env = wideSunEnvironment();
    const glm::dvec3 axis = env.map().toDirection(0, glm::dvec2(0.3, 0.6));
    const ProductWindow window = chooseWindow(env.map(), axis, 0.3, 7);
    ASSERT_FALSE(window.whole());
    // f(d) bilinear in the window-local coordinates (x, y) of d's square point right of x = 1/2,
    // where it starts from 0, and 0 left of it: bilinear within every leaf (the corners on
    // x = 1/2 come back from the direction round trip within 1e-16 of it).
    auto f = [&](const glm::dvec3& d) {
        const glm::dvec2 local = (octSquarePoint(env.map(), d) - window.origin()) / window.side();
        const double right = local.x - 0.5;
        return right > 1e-12 ? right * (1.0 + 3.0 * local.y) : 0.0;
    };
    auto values = [&](const std::vector<glm::dvec3>& d, std::vector<double>& out) {
        for (size_t i = 0; i < d.size(); ++i)
            out[i] = f(d[i]);
    };
    constexpr int kLevel = 4;
    const wavelet::SquareGrid centres =
        windowTabulateEnvWeightedBatch(env, window, kLevel, values, 2);
    const wavelet::SquareGrid corners =
        windowTabulateEnvWeightedCornersBatch(env, window, kLevel, values);
    const int side = 1 << kLevel;
    int lit = 0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            SCOPED_TRACE(testing::Message() << "leaf " << x << ", " << y);
            if (x < side / 2) { // every corner at local x <= 1/2 sees 0
                EXPECT_EQ(corners.at(x, y), 0.0);
                continue;
            }
            ++lit;
            EXPECT_NEAR(corners.at(x, y), centres.at(x, y), 1e-9 * centres.at(x, y));
        }
    EXPECT_EQ(lit, side * side / 2);
}

} // namespace
} // namespace wavelit::render
