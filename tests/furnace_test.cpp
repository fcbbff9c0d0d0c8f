// White furnace (issue 6 acceptance, issue 3's closed-form case): a sphere in a constant
// environment L, rendered with bounces = 1 by the CPU reference tracer. A convex object sees
// only the environment, so the pixel value is L × the directional albedo E(μo) of its BRDF at
// the pixel's view angle: exactly ρL for Lambert, and for GGX the E(μo) that dense quadrature of
// the C++ BRDF gives (plugins/brdf_albedo.h) — independent of the sampling code under test.
// Background pixels see L exactly; no pixel may be NaN or Inf.
#include "furnace_test_support.h"

#include "render/reference/cpu_camera.h"
#include "render/reference/cpu_path_tracer.h"
#include "render/reference/cpu_surface.h"
#include "render/session/integrator_factory.h"

#include "plugins/brdf.h"
#include "plugins/testing/brdf_albedo.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace wavelit {
namespace {

using namespace furnace_test;

TEST(Furnace, LambertSphereIsAlbedoTimesEnvironmentEverywhere) {
    scene::Material m;
    m.brdf = "lambert";
    m.baseColor = glm::vec3(0.8f, 0.5f, 0.2f);
    const glm::vec3 env(1.0f, 0.5f, 2.0f);
    Furnace f(m, env);
    auto tracer = render::createCpuPathTracer(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    for (int pass = 0; pass < 8; ++pass) ASSERT_TRUE((*tracer)->renderPass().ok());
    auto img = (*tracer)->image();
    ASSERT_TRUE(img.ok());
    expectFinite(*img);

    auto kinds = f.classify();
    int sphere = 0, background = 0;
    double worst = 0.0;
    for (int i = 0; i < kSize * kSize; ++i) {
        const glm::vec3& p = img->pixels[i];
        if (kinds[i] == PixelKind::Background) {
            ++background;
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], env[c], kExactTolerance);
        } else if (kinds[i] == PixelKind::Sphere) {
            ++sphere;
            for (int c = 0; c < 3; ++c) {
                double expected = double(m.baseColor[c]) * env[c];
                worst = std::max(worst, std::abs(p[c] - expected) / expected);
                ASSERT_NEAR(p[c], expected, kFurnaceTolerance * expected) << i << " channel " << c;
            }
        }
    }
    std::printf("[furnace] lambert: %d sphere px, %d background px, worst rel. error %.2e\n",
                sphere, background, worst);
    EXPECT_GT(sphere, 1000);
    EXPECT_GT(background, 500);
}

TEST(Furnace, LambertSphereUnderSkyOverBlackGroundSeesHalfSpaceIrradiance) {
    // Env: upper hemisphere L, lower hemisphere black (a 2×2 equirect: row 0 is the top, v < ½
    // is d.y > 0). A cosine-weighted hemisphere around n has the fraction (1 + n.y)/2 of its
    // mass above the horizon, so the pixel value is ρ L (1 + n_s.y)/2: this checks the env's
    // orientation and the tracer's frames, not only a constant.
    scene::Material m;
    m.baseColor = glm::vec3(0.6f);
    Furnace f(m, glm::vec3(1.0f));
    auto sky = std::make_shared<util::ImageRGB>(2, 2, glm::vec3(0.0f));
    sky->at(0, 0) = sky->at(1, 0) = glm::vec3(2.0f);
    f.scene->lighting.environment.image = sky;
    auto tracer = render::CpuPathTracer::create(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    // Each sample is ρL × Bernoulli((1 + n.y)/2); the dimmer lower half (~750 pixels, p ≈ 0.3)
    // needs 256 passes for a relative standard error of ~0.35%, a third of the 1% bound.
    for (int pass = 0; pass < 256; ++pass) ASSERT_TRUE((*tracer)->renderPass().ok());
    auto img = (*tracer)->image();
    expectFinite(*img);

    render::CpuCamera cam(f.scene->camera, kSize, kSize);
    auto kinds = f.classify();
    double rendered[2] = {0, 0}, expected[2] = {0, 0}; // upper and lower half of the image
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (kinds[y * kSize + x] != PixelKind::Sphere) continue;
            double e = 0.0;
            for (int a = 0; a < kSubpixels; ++a)
                for (int b = 0; b < kSubpixels; ++b) {
                    render::SurfacePoint sp;
                    ASSERT_TRUE(f.hits(cam, x, y, (a + 0.5f) / kSubpixels, (b + 0.5f) / kSubpixels,
                                       &sp));
                    e += 0.6 * 2.0 * 0.5 * (1.0 + sp.shading.y);
                }
            int half = y < kSize / 2 ? 0 : 1;
            expected[half] += e / (kSubpixels * kSubpixels);
            rendered[half] += img->at(x, y).x;
        }
    for (int half = 0; half < 2; ++half) {
        EXPECT_NEAR(rendered[half] / expected[half], 1.0, kFurnaceTolerance) << "half " << half;
        std::printf("[furnace] sky over black, %s half: rendered/expected = %.5f\n",
                    half == 0 ? "upper" : "lower", rendered[half] / expected[half]);
    }
    EXPECT_GT(expected[0], 2.0 * expected[1]); // the sky side really is the bright side
}

struct GgxCase {
    float roughness;
    glm::vec3 f0;
};

class GgxFurnace : public ::testing::TestWithParam<GgxCase> {};

TEST_P(GgxFurnace, SphereIsEnvironmentTimesDirectionalAlbedo) {
    scene::Material m;
    m.brdf = "ggx";
    m.roughness = GetParam().roughness;
    m.baseColor = GetParam().f0;
    const glm::vec3 env(1.0f, 0.5f, 2.0f);
    Furnace f(m, env);
    auto tracer = render::CpuPathTracer::create(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    const int passes = 64;
    for (int pass = 0; pass < passes; ++pass) ASSERT_TRUE((*tracer)->renderPass().ok());
    auto img = (*tracer)->image();
    ASSERT_TRUE(img.ok());
    expectFinite(*img);

    const AlbedoTable albedo(*plugins::findBrdf("ggx"), {m.baseColor, m.roughness});
    render::CpuCamera cam(f.scene->camera, kSize, kSize);
    auto kinds = f.classify();
    glm::dvec3 sumRendered(0.0), sumExpected(0.0);
    int sphere = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            int i = y * kSize + x;
            if (kinds[i] == PixelKind::Background) {
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(img->pixels[i][c], env[c], kExactTolerance);
                continue;
            }
            if (kinds[i] != PixelKind::Sphere) continue;
            ++sphere;
            // The pixel's expectation: E at the view angle averaged over its footprint.
            glm::dvec3 expected(0.0);
            for (int a = 0; a < kSubpixels; ++a)
                for (int b = 0; b < kSubpixels; ++b) {
                    render::SurfacePoint sp;
                    float u = (a + 0.5f) / kSubpixels, v = (b + 0.5f) / kSubpixels;
                    ASSERT_TRUE(f.hits(cam, x, y, u, v, &sp));
                    double mu = glm::dot(-cam.direction(x, y, u, v), sp.shading);
                    expected += albedo(mu);
                }
            expected *= glm::dvec3(env) / double(kSubpixels * kSubpixels);
            sumExpected += expected;
            sumRendered += glm::dvec3(img->pixels[i]);
        }
    EXPECT_GT(sphere, 1000);
    for (int c = 0; c < 3; ++c) {
        double ratio = sumRendered[c] / sumExpected[c];
        EXPECT_NEAR(ratio, 1.0, kFurnaceTolerance) << "channel " << c;
        std::printf("[furnace] ggx r=%.2f channel %d: rendered/expected = %.5f\n",
                    GetParam().roughness, c, ratio);
    }
}

// The white furnace for every plugin (issue 16: albedo <= 1 + 1e-3): baseColor 1, so the sphere
// under a constant environment L = 1 reflects E(wo) <= 1 at every view, by quadrature of eval()
// (the rendered sphere matches L x E per sampler: sampler_furnace_test.cpp). Near-mirror (r =
// 0.02) to rough, normal to grazing (89 degrees), and for anisotropic `ward` several azimuths of
// the view about the lobe's stretch. `measured`: tables of white `glossy` at r = 0.5 and 1 in
// the shipped example's 24 x 64 x 32 bins. A table too coarse for its lobe reflects more than
// arrives, whatever the plugin does: interpolating a convex peak between bin centres lies above
// it (r = 0.3 in 24 θh bins: 1.013 at normal view; r = 0.02: 4.6, the first θh centre at
// 6.8e-4 rad holding a lobe of α = 4e-4; docs/brdfs.md). 128 x 128 half-vector cells: ~1e-4
// relative (brdf_albedo.h), 10x under the bound.
TEST(Furnace, EveryPluginReflectsAtMostWhatArrives) {
    constexpr double kWhiteFurnaceBound = 1.0 + 1e-3;
    const float roughnesses[] = {0.02f, 0.3f, 1.0f};
    const float cosViews[] = {1.0f, 0.5f, 0.0872f, 0.0175f};
    const float azimuths[] = {0.0f, 0.8f, 1.5708f};
    int checked = 0;
    double worst = 0.0;
    std::string worstCase;
    auto check = [&](const plugins::Brdf& b, const plugins::BrdfParams& p, const std::string& label) {
        for (float c : cosViews)
            for (float phi : azimuths) {
                if (p.anisotropy == 0.0f && phi != azimuths[1]) continue; // isotropic: one azimuth
                const float s = std::sqrt(1.0f - c * c);
                const glm::vec3 wo(s * std::cos(phi), s * std::sin(phi), c);
                const glm::dvec3 e = plugins::directionalAlbedo(b, p, wo, 128, 128);
                for (int ch = 0; ch < 3; ++ch) {
                    EXPECT_LE(e[ch], kWhiteFurnaceBound) << label << " cos " << c << " phi " << phi;
                    if (e[ch] > worst) {
                        worst = e[ch];
                        worstCase = label + " cos " + std::to_string(c);
                    }
                }
                ++checked;
            }
    };
    for (const plugins::Brdf* b : plugins::brdfRegistry()) {
        if (plugins::brdfReadsFile(*b)) {
            for (float r : {0.5f, 1.0f}) {
                const auto table = furnace_test::glossyTable(r);
                ASSERT_TRUE(table);
                check(*b, plugins::BrdfParams(glm::vec3(1.0f), r, 0.0f, table),
                      std::string(b->name()) + " (glossy r=" + std::to_string(r) + ")");
            }
            continue;
        }
        for (float r : roughnesses)
            for (float a : {0.0f, 0.9f}) {
                if (a > 0.0f && b->gpuTwin().typeParameter == nullptr) continue; // reads no anisotropy
                check(*b, plugins::BrdfParams(glm::vec3(1.0f), r, a),
                      std::string(b->name()) + " r=" + std::to_string(r) + " a=" + std::to_string(a));
            }
    }
    std::printf("[furnace] white furnace: %d (plugin, setting, view) cases, highest albedo %.5f (%s)\n",
                checked, worst, worstCase.c_str());
    EXPECT_GT(checked, 60);
}

INSTANTIATE_TEST_SUITE_P(Roughness, GgxFurnace,
                         ::testing::Values(GgxCase{0.05f, glm::vec3(1.0f)},
                                           GgxCase{0.3f, glm::vec3(0.9f, 0.6f, 0.3f)},
                                           GgxCase{1.0f, glm::vec3(1.0f)},
                                           GgxCase{0.6f, glm::vec3(0.04f)}));

} // namespace
} // namespace wavelit
