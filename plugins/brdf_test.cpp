// The checks every BRDF plugin must pass (architecture.md §8), run for each registered plugin over
// shading configurations that include grazing views (θo = 85°), a mirror-like lobe (r = 0.02)
// and the roughest one (r = 1): chi-square goodness-of-fit of sample() against pdf(), pdf
// consistency, Monte Carlo albedo against quadrature, reciprocity and energy conservation.
#include "plugins/brdf.h"
#include "plugins/brdf_table.h"
#include "plugins/testing/brdf_albedo.h"

#include "util/direction_chi_square.h"
#include "util/hemisphere_sampling.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>

#include <unistd.h>

namespace wavelit::plugins {
namespace {

// Per-configuration significance of the goodness-of-fit test (the brief's p > 0.01; the seed is
// fixed, so a pass is reproducible rather than lucky by 1%).
constexpr double kChiSquareAlpha = 0.01;
constexpr int kChiSquareSamples = 1'000'000;
// sample() recomputes f and pdf from wi through the same code as pdf(), so they agree to float
// rounding of identical operations.
constexpr float kPdfRelTolerance = 1e-5f;
// Monte Carlo albedo vs quadrature: 3 standard errors, plus the quadrature's own error, which
// dominates for zero-variance estimators such as Lambert's. Measured 256² vs 768² cells: up to
// 2e-5 relative (the horizon cut is a kink inside cells), 5e-5 for GGX r = 1 at θo = 85°.
constexpr double kStandardErrors = 3.0;
constexpr double kQuadratureRelTolerance = 1e-4;
// Invert round trip: angle between a direction and its round trip, in radians. Measured worst
// 6.5e-5 (GGX r = 0.2: float error of h/alpha and the disk warp), 2e-6 for Lambert.
constexpr float kInvertAngleTolerance = 2e-4f;
// Reciprocity: the formulas are symmetric; float evaluation order differs (h from wo + wi).
// Issue 16 asks for 1e-5 relative.
constexpr float kReciprocityRelTolerance = 1e-5f;
// Energy: single scattering cannot create energy; the quadrature error bounds the slack.
constexpr double kAlbedoSlack = 1e-4;

struct Case {
    Case(std::string name, glm::vec3 color, float r, float theta, double exponent, float aniso = 0.0f)
        : brdf(std::move(name)), baseColor(color), roughness(r), thetoDeg(theta),
          thetaExponent(exponent), anisotropy(aniso) {}
    std::string brdf;
    glm::vec3 baseColor;
    float roughness;
    float thetoDeg;
    double thetaExponent; // chi-square grid refinement toward the lobe axis
    float anisotropy;
};

// The shipped example measured file (resources/brdfs/README.md), loaded once.
std::shared_ptr<const BrdfTable> exampleTable() {
    static const std::shared_ptr<const BrdfTable> kTable = [] {
        auto t = loadMerlBrdf(std::string(WAVELIT_RESOURCE_DIR) + "/brdfs/glossy-copper-r05.binary");
        return t ? *t : nullptr;
    }();
    return kTable;
}

// A sharper table than the example: `glossy` r = 0.2 (α = 0.04), colour 0.9, in MERL's 90 θh
// bins (~14 of them up to θh = α), 90 x 64 x 32, written and read back through the file format.
// Interpolating its peak between bin centres overshoots the model's albedo (+0.4% here, +2.8% in
// 32 θh bins: docs/brdfs.md); a white table of it would reflect 1.002 at normal view, so it is
// tabulated at 0.9, as measured materials are coloured.
std::shared_ptr<const BrdfTable> sharpTable() {
    static const std::shared_ptr<const BrdfTable> kTable = [] {
        const std::vector<char> bytes =
            tabulateMerlBrdf(*findBrdf("glossy"), BrdfParams(glm::vec3(0.9f), 0.2f), 90, 64, 32);
        // One name per process: ctest -j runs each case as its own process, and two of them
        // writing, reading and removing one shared path read each other's half-written file
        // (a table of zeros: WhiteAlbedoAtMostOne failed with albedo 0 in a CI run).
        const std::string path = ::testing::TempDir() + "wavelit_brdf_test_sharp_" +
                                 std::to_string(::getpid()) + ".binary";
        std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        auto t = loadMerlBrdf(path);
        std::remove(path.c_str());
        return t ? *t : nullptr;
    }();
    return kTable;
}

// `measured` reads no roughness: here it picks the table, 0.2 the sharp one, else the example.
BrdfParams paramsOf(const std::string& brdf, glm::vec3 color, float roughness, float anisotropy) {
    if (brdf != "measured") return BrdfParams(color, roughness, anisotropy);
    return BrdfParams(color, roughness, anisotropy, roughness == 0.2f ? sharpTable() : exampleTable());
}

std::ostream& operator<<(std::ostream& os, const Case& c) {
    return os << c.brdf << " r=" << c.roughness << " a=" << c.anisotropy << " θo=" << c.thetoDeg;
}

glm::vec3 viewDirection(float thetaDeg) {
    float t = glm::radians(thetaDeg);
    // A non-zero azimuth so no test relies on wo lying in the xz plane.
    float phi = 0.7f;
    return glm::vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
}

class BrdfTest : public ::testing::TestWithParam<Case> {
protected:
    const Brdf& brdf() const {
        const Brdf* b = findBrdf(GetParam().brdf);
        EXPECT_NE(b, nullptr);
        return *b;
    }
    BrdfParams params() const {
        const Case& c = GetParam();
        return paramsOf(c.brdf, c.baseColor, c.roughness, c.anisotropy);
    }
    glm::vec3 wo() const { return viewDirection(GetParam().thetoDeg); }
};

TEST_P(BrdfTest, SampledDirectionsFollowPdf) {
    const Brdf& b = brdf();
    BrdfParams p = params();
    glm::vec3 o = wo();
    util::DirectionGrid grid;
    // Axis on the lobe: the reflection vector (for Lambert any axis works).
    grid.axis = glm::vec3(-o.x, -o.y, o.z);
    grid.thetaBins = 40;
    grid.phiBins = 80;
    grid.thetaExponent = GetParam().thetaExponent;
    auto result = util::directionChiSquare(
        [&](glm::vec2 u) -> std::optional<glm::vec3> {
            BrdfSample s = b.sample(p, o, u.x, u.y);
            if (!s.valid) return std::nullopt;
            return s.wi;
        },
        [&](const glm::vec3& wi) { return double(b.pdf(p, o, wi)); }, grid, kChiSquareSamples,
        0x5eed);
    EXPECT_GT(result.chi.pValue, kChiSquareAlpha)
        << "chi2=" << result.chi.statistic << " dof=" << result.chi.degreesOfFreedom
        << " ∫pdf=" << result.integratedPdf << " invalid=" << result.invalidSamples;
    EXPECT_EQ(result.chi.observedOutsideSupport, 0.0);
    EXPECT_LE(result.integratedPdf, 1.0 + 1e-3);
    std::printf("[chi2] %s r=%.2f theta_o=%.0f: p=%.3f dof=%d invalid=%.4f%%\n",
                GetParam().brdf.c_str(), GetParam().roughness, GetParam().thetoDeg,
                result.chi.pValue, result.chi.degreesOfFreedom,
                100.0 * result.invalidSamples / kChiSquareSamples);
}

TEST_P(BrdfTest, PdfOfSampleEqualsReturnedPdfAndEvalEqualsReturnedF) {
    const Brdf& b = brdf();
    BrdfParams p = params();
    glm::vec3 o = wo();
    util::Pcg32 rng(11);
    int valid = 0;
    for (int i = 0; i < 20000; ++i) {
        BrdfSample s = b.sample(p, o, rng.nextFloat(), rng.nextFloat());
        if (!s.valid) continue;
        ++valid;
        ASSERT_GT(s.pdf, 0.0f);
        ASSERT_GT(s.wi.z, 0.0f);
        ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-5f);
        float q = b.pdf(p, o, s.wi);
        ASSERT_NEAR(q, s.pdf, kPdfRelTolerance * s.pdf);
        glm::vec3 f = b.eval(p, o, s.wi);
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(f[c], s.f[c], kPdfRelTolerance * s.f[c]);
    }
    EXPECT_GT(valid, 10000);
}

TEST_P(BrdfTest, InvertRoundTrips) {
    // Round trip in direction space (sample(invert(wi)) = wi): in u space a mirror-like lobe
    // amplifies float error by 1/alpha, but the direction must come back.
    const Brdf& b = brdf();
    BrdfParams p = params();
    glm::vec3 o = wo();
    util::Pcg32 rng(31);
    int checked = 0;
    float worst = 0.0f;
    for (int i = 0; i < 5000; ++i) {
        float u1 = rng.nextFloat();
        float u2 = rng.nextFloat();
        BrdfSample s = b.sample(p, o, u1, u2);
        if (!s.valid) continue;
        std::optional<glm::vec2> u = b.invert(p, o, s.wi);
        ASSERT_TRUE(u.has_value());
        ASSERT_GE(u->x, 0.0f);
        ASSERT_LE(u->x, 1.0f);
        BrdfSample back = b.sample(p, o, u->x, u->y);
        ASSERT_TRUE(back.valid);
        float angle = glm::length(back.wi - s.wi); // chord ≈ angle for small angles
        worst = std::max(worst, angle);
        ASSERT_LT(angle, kInvertAngleTolerance) << u1 << "," << u2;
        ++checked;
    }
    EXPECT_GT(checked, 2000);
    std::printf("[invert] %s r=%.2f theta_o=%.0f: worst round-trip angle %.2e rad\n",
                GetParam().brdf.c_str(), GetParam().roughness, GetParam().thetoDeg, worst);
    EXPECT_FALSE(b.invert(p, o, glm::vec3(0.0f, 0.6f, -0.8f)).has_value());
}

TEST_P(BrdfTest, MonteCarloAlbedoMatchesQuadrature) {
    const Brdf& b = brdf();
    BrdfParams p = params();
    glm::vec3 o = wo();
    const int n = 400000;
    glm::dvec3 sum(0.0), sum2(0.0);
    util::Pcg32 rng(23);
    for (int i = 0; i < n; ++i) {
        BrdfSample s = b.sample(p, o, rng.nextFloat(), rng.nextFloat());
        if (!s.valid) continue;
        glm::dvec3 w = glm::dvec3(s.f) * double(s.wi.z) / double(s.pdf);
        sum += w;
        sum2 += w * w;
    }
    glm::dvec3 mean = sum / double(n);
    glm::dvec3 var = sum2 / double(n) - mean * mean;
    glm::dvec3 reference = directionalAlbedo(b, p, o);
    for (int c = 0; c < 3; ++c) {
        double se = std::sqrt(std::max(0.0, var[c]) / n);
        EXPECT_NEAR(mean[c], reference[c],
                    kStandardErrors * se + kQuadratureRelTolerance * reference[c])
            << "channel " << c << " se=" << se;
    }
}

TEST_P(BrdfTest, QuadratureIsConverged) {
    const Brdf& b = brdf();
    glm::dvec3 coarse = directionalAlbedo(b, params(), wo(), 256, 256);
    glm::dvec3 fine = directionalAlbedo(b, params(), wo(), 768, 768);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(coarse[c], fine[c], kQuadratureRelTolerance * fine[c]);
}

TEST_P(BrdfTest, ReciprocalAndNonNegative) {
    const Brdf& b = brdf();
    BrdfParams p = params();
    util::Pcg32 rng(5);
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 a = util::sampleUniformHemisphere({rng.nextFloat(), rng.nextFloat()});
        glm::vec3 c = util::sampleUniformHemisphere({rng.nextFloat(), rng.nextFloat()});
        if (a.z <= 1e-3f || c.z <= 1e-3f) continue;
        glm::vec3 fac = b.eval(p, a, c), fca = b.eval(p, c, a);
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(fac[k], 0.0f);
            ASSERT_NEAR(fac[k], fca[k], kReciprocityRelTolerance * std::max(fac[k], 1e-6f));
        }
    }
}

TEST_P(BrdfTest, WhiteAlbedoAtMostOne) {
    const Brdf& b = brdf();
    BrdfParams p = params();
    p.baseColor = glm::vec3(1.0f);
    glm::dvec3 e = directionalAlbedo(b, p, wo());
    for (int c = 0; c < 3; ++c) EXPECT_LE(e[c], 1.0 + kAlbedoSlack);
    // And it reflects something: a broken eval returning 0 would pass ≤ 1. Phong, Blinn-Phong
    // and Ward have no Fresnel rise and no shadowing that compensates their cut lobe, so at
    // grazing views their albedo falls to about cosθo (0.087 at 85°): the bound follows it.
    const bool darkensAtGrazing = GetParam().brdf == "phong" || GetParam().brdf == "blinn" ||
                                  GetParam().brdf == "ward";
    EXPECT_GT(e[0], darkensAtGrazing ? 0.5 * wo().z : 0.3);
}

TEST_P(BrdfTest, BelowHorizonIsZero) {
    const Brdf& b = brdf();
    BrdfParams p = params();
    glm::vec3 o = wo();
    glm::vec3 below(0.3f, 0.1f, -0.9f);
    below = glm::normalize(below);
    EXPECT_EQ(b.eval(p, o, below), glm::vec3(0.0f));
    EXPECT_EQ(b.pdf(p, o, below), 0.0f);
    EXPECT_FALSE(b.sample(p, below, 0.3f, 0.6f).valid);
}

const glm::vec3 kTinted(0.9f, 0.5f, 0.2f);

INSTANTIATE_TEST_SUITE_P(
    Lambert, BrdfTest,
    ::testing::Values(Case{"lambert", kTinted, 0.5f, 0.0f, 1.0},
                      Case{"lambert", kTinted, 0.5f, 30.0f, 1.0},
                      Case{"lambert", glm::vec3(1.0f), 0.5f, 60.0f, 1.0},
                      Case{"lambert", kTinted, 0.5f, 85.0f, 1.0},
                      Case{"lambert", glm::vec3(0.05f), 0.5f, 45.0f, 1.0},
                      Case{"lambert", kTinted, 0.5f, 89.0f, 1.0}));

INSTANTIATE_TEST_SUITE_P(
    Ggx, BrdfTest,
    ::testing::Values(Case{"ggx", kTinted, 0.02f, 0.0f, 3.0},
                      Case{"ggx", kTinted, 0.02f, 45.0f, 3.0},
                      Case{"ggx", kTinted, 0.02f, 85.0f, 3.0},
                      Case{"ggx", kTinted, 0.05f, 70.0f, 3.0},
                      Case{"ggx", kTinted, 0.2f, 0.0f, 2.0},
                      Case{"ggx", glm::vec3(0.04f), 0.2f, 60.0f, 2.0},
                      Case{"ggx", kTinted, 0.5f, 30.0f, 1.0},
                      Case{"ggx", kTinted, 0.5f, 85.0f, 1.0},
                      Case{"ggx", glm::vec3(1.0f), 1.0f, 0.0f, 1.0},
                      Case{"ggx", kTinted, 1.0f, 85.0f, 1.0}));

// Issue 16's plugins: roughness 0.02 is the near-mirror setting, θo = 85-89° the grazing one.
INSTANTIATE_TEST_SUITE_P(
    Glossy, BrdfTest,
    ::testing::Values(Case{"glossy", kTinted, 0.02f, 0.0f, 3.0},
                      Case{"glossy", kTinted, 0.02f, 85.0f, 3.0},
                      Case{"glossy", kTinted, 0.2f, 60.0f, 2.0},
                      Case{"glossy", kTinted, 0.5f, 30.0f, 1.0},
                      Case{"glossy", glm::vec3(1.0f), 1.0f, 85.0f, 1.0}));

INSTANTIATE_TEST_SUITE_P(
    Phong, BrdfTest,
    ::testing::Values(Case{"phong", kTinted, 0.02f, 0.0f, 3.0},
                      Case{"phong", kTinted, 0.02f, 85.0f, 3.0},
                      Case{"phong", kTinted, 0.2f, 60.0f, 2.0},
                      Case{"phong", kTinted, 0.5f, 30.0f, 1.0},
                      Case{"phong", glm::vec3(1.0f), 1.0f, 85.0f, 1.0}));

INSTANTIATE_TEST_SUITE_P(
    Blinn, BrdfTest,
    ::testing::Values(Case{"blinn", kTinted, 0.02f, 0.0f, 3.0},
                      Case{"blinn", kTinted, 0.02f, 85.0f, 3.0},
                      Case{"blinn", kTinted, 0.2f, 60.0f, 2.0},
                      Case{"blinn", kTinted, 0.5f, 30.0f, 1.0},
                      Case{"blinn", glm::vec3(1.0f), 1.0f, 85.0f, 1.0}));

INSTANTIATE_TEST_SUITE_P(
    Ward, BrdfTest,
    ::testing::Values(Case{"ward", kTinted, 0.02f, 0.0f, 3.0},
                      Case{"ward", kTinted, 0.02f, 85.0f, 3.0},
                      Case{"ward", kTinted, 0.2f, 60.0f, 2.0},
                      Case{"ward", kTinted, 0.5f, 30.0f, 1.0},
                      Case{"ward", glm::vec3(1.0f), 1.0f, 85.0f, 1.0},
                      Case{"ward", kTinted, 0.2f, 45.0f, 2.0, 0.8f},
                      Case{"ward", kTinted, 0.05f, 85.0f, 3.0, 1.0f},
                      Case{"ward", glm::vec3(1.0f), 0.7f, 70.0f, 1.0, 0.5f}));

// Two tables: the shipped example (glossy r = 0.5; "roughness" 0.5 here) and a sharper glossy
// r = 0.2 table (0.2: paramsOf), at views from normal to grazing.
INSTANTIATE_TEST_SUITE_P(
    Measured, BrdfTest,
    ::testing::Values(Case{"measured", glm::vec3(1.0f), 0.5f, 0.0f, 1.0},
                      Case{"measured", kTinted, 0.5f, 45.0f, 1.0},
                      Case{"measured", glm::vec3(1.0f), 0.5f, 85.0f, 1.0},
                      Case{"measured", kTinted, 0.5f, 89.0f, 1.0},
                      Case{"measured", glm::vec3(1.0f), 0.2f, 0.0f, 2.0},
                      Case{"measured", kTinted, 0.2f, 60.0f, 2.0},
                      Case{"measured", glm::vec3(1.0f), 0.2f, 85.0f, 2.0}));

TEST(BrdfRegistry, FindsEveryPluginByNameAndDescribesItsParameters) {
    auto names = brdfNames();
    const std::vector<std::string> expected{"lambert", "ggx",  "glossy",  "phong",
                                            "blinn",   "ward", "measured"};
    ASSERT_EQ(names, expected);
    EXPECT_EQ(names[0], "lambert");
    EXPECT_EQ(names[1], "ggx");
    EXPECT_EQ(findBrdf("nonexistent"), nullptr);
    for (const auto& n : names) {
        const Brdf* b = findBrdf(n);
        ASSERT_NE(b, nullptr);
        EXPECT_EQ(n, b->name());
        ASSERT_FALSE(b->parameters().empty());
        EXPECT_STREQ(b->parameters()[0].name, "baseColor");
        for (const auto& info : b->parameters()) {
            EXPECT_LE(info.minValue, info.defaultValue.x);
            EXPECT_GE(info.maxValue, info.defaultValue.x);
            EXPECT_GT(std::string(info.tooltip).size(), 10u);
        }
    }
    ASSERT_EQ(findBrdf("ggx")->parameters().size(), 2u);
    EXPECT_STREQ(findBrdf("ggx")->parameters()[1].name, "roughness");
}

} // namespace
} // namespace wavelit::plugins
