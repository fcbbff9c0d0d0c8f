// `mis` over an environment and analytic lights together in the CPU reference tracer: its mean
// equals `bsdf`'s, which reaches the same light by other techniques (docs/estimator.md).
#include "render/reference/cpu_path_tracer.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/cpu_test_tracer.h"
#include "render/testing/pixel_moments.h"
#include "util/image.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

namespace wavelit::render {
namespace {

constexpr int kSize = 32;
// The two samplers agree within this many combined standard errors.
constexpr double kSamplerSigmas = 3.0;

TEST(CpuPathTracerEnvLights, MisOverEnvAndLightsAgreesWithBsdf) {
    // `mis` over a lit env with analytic lights (env NEE by the alias-table env technique, light
    // NEE, each MIS-weighted against the BSDF continuation): its mean must equal `bsdf`'s (lights
    // by NEE, env by BSDF sampling alone). A glossy plane that mirrors a sphere light and a rect
    // light, an env with a one-texel sun, two bounces.
    scene::Material ggx;
    ggx.brdf = "ggx";
    ggx.roughness = 0.3f;
    ggx.baseColor = glm::vec3(0.9f);
    auto s = makePlaneScene(ggx);
    s->camera.position = glm::vec3(0.0f, 1.0f, 2.0f);
    // An env that matters as much as the lights: a bright sky, a dim ground, a one-texel sun.
    auto image = std::make_shared<util::ImageRGB>(16, 8, glm::vec3(0.05f));
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 16; ++x) image->at(x, y) = glm::vec3(2.0f, 2.5f, 3.0f);
    image->at(7, 2) = glm::vec3(400.0f);
    s->lighting.environment.image = image;
    s->lighting.environment.intensity = 1.0f;
    scene::Light sphere;
    sphere.type = scene::LightType::Sphere;
    sphere.position = glm::vec3(0.0f, 1.0f, -2.0f);
    sphere.intensity = 30.0f;
    sphere.radius = 0.3f;
    s->lighting.lights.push_back(sphere);
    scene::Light rect = sphere;
    rect.type = scene::LightType::Rect;
    rect.position = glm::vec3(1.0f, 1.5f, -1.0f);
    rect.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.5f));
    rect.size = glm::vec2(1.0f, 0.6f);
    s->lighting.lights.push_back(rect);
    const int passes = 128;
    PixelMoments m[2];
    const SamplerKind kinds[2] = {SamplerKind::Bsdf, SamplerKind::Mis};
    for (int i = 0; i < 2; ++i) {
        RenderOptions o;
        o.width = o.height = kSize;
        o.bounces = 2;
        o.seed = 5;
        o.device = DeviceChoice::Cpu;
        o.sampler = kinds[i];
        auto tracer = makeCpuTestTracer(s, o);
        ASSERT_TRUE(tracer);
        m[i] = pixelMoments(*tracer, kSize, kSize, passes);
    }
    const double sigma = std::hypot(m[0].standardError, m[1].standardError);
    EXPECT_NEAR(m[1].mean, m[0].mean, kSamplerSigmas * sigma);
    EXPECT_GT(m[0].mean, 0.0);
    std::printf("[ env + lights ] bsdf %.4f±%.4f mis %.4f±%.4f (|z| %.2f); "
                "variance mis/bsdf %.2f\n",
                m[0].mean, m[0].standardError, m[1].mean, m[1].standardError,
                std::abs(m[1].mean - m[0].mean) / sigma, m[1].pixelVariance / m[0].pixelVariance);
}

} // namespace
} // namespace wavelit::render
