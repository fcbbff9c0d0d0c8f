// The exact env technique (equirect_env_sampler.h): a one-texel sun at 1e6 x the sky, where the
// conservative octahedral map dilated the sun over its neighbours; chi-square over the equirect
// texels against the tabulated probabilities, the sun texel's probability equal to its share of
// luminance x solid angle, pdf(sample) == the returned pdf, and an all-black map without light.
#include "render/sampling/equirect_env_sampler.h"
#include "render/sampling/sampler_environment.h"
#include "util/chi_square.h"
#include "util/image.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace wavelit::render {
namespace {

constexpr int kW = 64, kH = 32;
constexpr int kSunX = 37, kSunY = 9;

scene::Environment sunSky(double ratio) {
    scene::Environment env;
    auto image = std::make_shared<util::ImageRGB>(kW, kH, glm::vec3(0.0f));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            image->at(x, y) = y < kH / 2 ? glm::vec3(0.5f, 0.6f, 1.0f) : glm::vec3(0.05f);
    image->at(kSunX, kSunY) = glm::vec3(float(ratio));
    env.image = image;
    env.rotationDeg = 25.0f;
    return env;
}

double texelSolidAngle(int y) {
    const double pi = std::numbers::pi;
    return 2.0 * pi / kW * (std::cos(pi * y / kH) - std::cos(pi * (y + 1) / kH));
}

TEST(EquirectEnvSampler, OneTexelSunChiSquareAndExactPdf) {
    const scene::Environment env = sunSky(1e6);
    const EquirectEnvSampler s = EquirectEnvSampler::build(env);
    ASSERT_TRUE(s.hasLight());
    // Exact probabilities: luminance x solid angle over the total.
    double total = 0.0;
    std::vector<double> mass(size_t(kW * kH));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            mass[size_t(y * kW + x)] =
                double(util::luminance(env.image->at(x, y))) * texelSolidAngle(y);
            total += mass[size_t(y * kW + x)];
        }
    double sumProbability = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const double p = s.texelPdf(x, y) * texelSolidAngle(y);
            EXPECT_NEAR(p, mass[size_t(y * kW + x)] / total, 1e-9 * mass[size_t(y * kW + x)] / total + 1e-15);
            sumProbability += p;
        }
    EXPECT_NEAR(sumProbability, 1.0, 1e-9);

    // Draws binned by the texel the tracer's lookup reads; pdf(sample) == returned pdf.
    const SamplerEnvironment view = SamplerEnvironment::build(env);
    const CpuEnvironment lookup(env);
    constexpr int kSamples = 200000;
    std::vector<double> observed(size_t(kW * kH), 0.0), expected(size_t(kW * kH));
    for (size_t i = 0; i < expected.size(); ++i)
        expected[i] = kSamples * mass[i] / total;
    util::Pcg32 rng(17);
    int mismatches = 0;
    for (int i = 0; i < kSamples; ++i) {
        const glm::dvec2 u(rng.nextDouble(), rng.nextDouble());
        const wavelet::DirectionSample d = view.sampleLocal(u);
        const glm::vec3 wi(view.toWorld(d.direction));
        const glm::vec2 uv = lookup.equirect(wi);
        const int x = std::min(int(uv.x * kW), kW - 1), y = std::min(int(uv.y * kH), kH - 1);
        observed[size_t(y * kW + x)] += 1.0;
        if (std::abs(view.pdfWorld(wi) - d.pdf) > 1e-9 * d.pdf)
            ++mismatches;
    }
    EXPECT_LE(mismatches, 2);
    const util::ChiSquareResult r = util::chiSquareTest(observed, expected);
    EXPECT_EQ(r.observedOutsideSupport, 0.0);
    EXPECT_GT(r.pValue, 1e-3) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    // The sun's own pdf is its radiance's share: 1e6 x a sky texel's of the same row.
    EXPECT_NEAR(s.texelPdf(kSunX, kSunY) / s.texelPdf(kSunX + 1, kSunY),
                1e6 / double(util::luminance(glm::vec3(0.5f, 0.6f, 1.0f))), 1e-3 * 1e6);
}

TEST(EquirectEnvSampler, AllBlackHasNoLight) {
    scene::Environment env;
    env.image = std::make_shared<util::ImageRGB>(kW, kH, glm::vec3(0.0f));
    const EquirectEnvSampler s = EquirectEnvSampler::build(env);
    EXPECT_FALSE(s.hasLight());
    EXPECT_EQ(s.pdfUv({0.3f, 0.4f}), 0.0);
    const SamplerEnvironment view = SamplerEnvironment::build(env);
    EXPECT_FALSE(view.hasLight());
    EXPECT_EQ(view.pdfWorld(glm::vec3(0.0f, 1.0f, 0.0f)), 0.0);
}

TEST(EquirectEnvSampler, ConstantEnvironmentIsUniform) {
    scene::Environment env; // no image: intensity x tint everywhere
    const EquirectEnvSampler s = EquirectEnvSampler::build(env);
    ASSERT_TRUE(s.hasLight());
    double pdf = 0.0;
    s.sampleLocal({0.3, 0.7}, pdf);
    EXPECT_NEAR(pdf, 1.0 / (4.0 * std::numbers::pi), 1e-12);
}

} // namespace
} // namespace wavelit::render
