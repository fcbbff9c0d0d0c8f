// The `uniform` and `cosine` direction samplers (architecture.md §5.B) and the shared shading frame:
// chi-square against their pdfs, pdf consistency and invert round trips (architecture.md §9: every sampler).
#include "util/hemisphere_sampling.h"

#include "util/direction_chi_square.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <optional>

namespace wavelit::util {
namespace {

constexpr double kChiSquareAlpha = 0.01;
constexpr int kSamples = 500'000;
// Round trips go through sqrt/atan2/cos in float: a few ulps of a value in [0, 1] each.
constexpr float kRoundTripTolerance = 2e-5f;

TEST(HemisphereSampling, CosineFollowsItsPdf) {
    DirectionGrid grid;
    auto r = directionChiSquare([](glm::vec2 u) -> std::optional<glm::vec3> {
        return sampleCosineHemisphere(u);
    }, [](const glm::vec3& w) { return double(cosineHemispherePdf(w)); }, grid, kSamples, 1);
    EXPECT_GT(r.chi.pValue, kChiSquareAlpha) << r.chi.statistic << " dof " << r.chi.degreesOfFreedom;
    EXPECT_NEAR(r.integratedPdf, 1.0, 1e-4);
}

TEST(HemisphereSampling, UniformFollowsItsPdf) {
    DirectionGrid grid;
    grid.axis = glm::normalize(glm::vec3(0.3f, 0.4f, 0.5f)); // any axis: the grid is just cells
    auto r = directionChiSquare([](glm::vec2 u) -> std::optional<glm::vec3> {
        return sampleUniformHemisphere(u);
    }, [](const glm::vec3& w) { return double(uniformHemispherePdf(w)); }, grid, kSamples, 1);
    EXPECT_GT(r.chi.pValue, kChiSquareAlpha) << r.chi.statistic << " dof " << r.chi.degreesOfFreedom;
}

TEST(DirectionChiSquare, RejectsSamplesFromAnotherDistribution) {
    // Cosine samples judged against the uniform pdf must fail: the test has power.
    DirectionGrid grid;
    auto r = directionChiSquare([](glm::vec2 u) -> std::optional<glm::vec3> {
        return sampleCosineHemisphere(u);
    }, [](const glm::vec3& w) { return double(uniformHemispherePdf(w)); }, grid, 100'000, 3);
    EXPECT_LT(r.chi.pValue, 1e-6);
}

TEST(DirectionChiSquare, CountsInvalidSamplesAgainstTheMissingMass) {
    // Half the samples are dropped, and the pdf says half the mass is missing: consistent.
    DirectionGrid grid;
    auto r = directionChiSquare([](glm::vec2 u) -> std::optional<glm::vec3> {
        if (u.y >= 0.5f) return std::nullopt;
        return sampleUniformHemisphere({u.x, u.y * 2.0f});
    }, [](const glm::vec3& w) { return 0.5 * uniformHemispherePdf(w); }, grid, 200'000, 4);
    EXPECT_GT(r.chi.pValue, kChiSquareAlpha);
    EXPECT_NEAR(r.integratedPdf, 0.5, 1e-4);
    // ... and a sampler that loses mass its pdf does not admit fails.
    auto bad = directionChiSquare([](glm::vec2 u) -> std::optional<glm::vec3> {
        if (u.y >= 0.9f) return std::nullopt;
        return sampleUniformHemisphere({u.x, u.y / 0.9f});
    }, [](const glm::vec3& w) { return double(uniformHemispherePdf(w)); }, grid, 200'000, 4);
    EXPECT_LT(bad.chi.pValue, 1e-6);
}

TEST(HemisphereSampling, PdfsAreConsistentAndInvertRoundTrips) {
    Pcg32 rng(5);
    for (int i = 0; i < 10000; ++i) {
        glm::vec2 u(rng.nextFloat(), rng.nextFloat());
        glm::vec3 c = sampleCosineHemisphere(u);
        ASSERT_NEAR(glm::length(c), 1.0f, 1e-5f);
        ASSERT_NEAR(cosineHemispherePdf(c), c.z / kPi, 1e-6f);
        glm::vec2 uc = invertCosineHemisphere(c);
        ASSERT_NEAR(uc.x, u.x, kRoundTripTolerance) << u.x << "," << u.y;
        ASSERT_NEAR(uc.y, u.y, kRoundTripTolerance) << u.x << "," << u.y;

        glm::vec3 w = sampleUniformHemisphere(u);
        ASSERT_NEAR(glm::length(w), 1.0f, 1e-5f);
        ASSERT_EQ(uniformHemispherePdf(w), 0.5f / kPi);
        glm::vec2 uu = invertUniformHemisphere(w);
        ASSERT_NEAR(uu.x, u.x, kRoundTripTolerance);
        // φ wraps: u.y near 1 may come back near 0.
        float dy = std::abs(uu.y - u.y);
        ASSERT_LT(std::min(dy, 1.0f - dy), kRoundTripTolerance);
    }
    EXPECT_EQ(cosineHemispherePdf(glm::vec3(0, 0, -1)), 0.0f);
    EXPECT_EQ(uniformHemispherePdf(glm::vec3(0, 0, -1)), 0.0f);
}

TEST(HemisphereSampling, ConcentricDiskPreservesAreaAndInverts) {
    // Area preservation: a uniform grid of u lands uniformly — mean radius² of a uniform disk is 1/2.
    double r2 = 0.0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            glm::vec2 p = sampleConcentricDisk({(i + 0.5f) / n, (j + 0.5f) / n});
            r2 += double(p.x) * p.x + double(p.y) * p.y;
        }
    EXPECT_NEAR(r2 / (n * n), 0.5, 1e-4);
    EXPECT_EQ(invertConcentricDisk(glm::vec2(0.0f)), glm::vec2(0.5f));
}

TEST(Frame, IsOrthonormalAndRoundTrips) {
    Pcg32 rng(6);
    for (int i = 0; i < 1000; ++i) {
        glm::vec3 n = glm::normalize(glm::vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) -
                                     glm::vec3(0.5f));
        if (i == 0) n = glm::vec3(0, 0, -1); // the branch point of Duff's construction
        Frame f = Frame::fromNormal(n);
        ASSERT_NEAR(glm::dot(f.t, f.b), 0.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(f.t, f.n), 0.0f, 1e-5f);
        ASSERT_NEAR(glm::length(f.t), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::length(f.b), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::dot(glm::cross(f.t, f.b), n), 1.0f, 1e-5f); // right-handed
        glm::vec3 w = glm::normalize(glm::vec3(0.2f, -0.7f, 0.4f));
        glm::vec3 back = f.toWorld(f.toLocal(w));
        ASSERT_NEAR(glm::length(back - w), 0.0f, 1e-5f);
        ASSERT_NEAR(f.toLocal(n).z, 1.0f, 1e-5f);
    }
}

} // namespace
} // namespace wavelit::util
