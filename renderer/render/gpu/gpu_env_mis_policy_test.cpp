// The `wavelet` policy EnvMis (issue 12, docs/performance.md "Wavelet pass cost, round 3" and
// "Equal time, round 5"): a scene whose every material is EnvMis (hemisphere-wide lobes under any
// env; mirror lobes far narrower than the env) draws from no product.
// Its vertices use `mis`'s technique with the same random numbers, so a `wavelet` render equals
// the `mis` render bit for bit on both tracers, and the Vulkan kernel is compiled without the
// product code (it must still compile and run under validation).
#include "render/sampling/product/env_product_tables.h"
#include "render/sampling/sampler_environment.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/sampler_test_envs.h"
#include "render/testing/test_integrator.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace wavelit::render {
namespace {

// A Lambert sphere under a sky whose sun is `sunRatio` times the sky's mean: the policy is EnvMis
// whether the sun holds the light (1e5) or the sky does (1: an env as wide as the cosine lobe).
std::shared_ptr<scene::Scene> lambertUnderSky(double sunRatio) {
    scene::Material m;
    m.id = 1;
    m.name = "matte";
    m.brdf = "lambert";
    m.baseColor = glm::vec3(0.7f);
    auto s = makeFurnaceScene(m, glm::vec3(1.0f), 32, 16);
    s->lighting.environment =
        makeSunSkyEnvironment(64, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), sunRatio);
    return s;
}

std::shared_ptr<scene::Scene> lambertUnderSun() { return lambertUnderSky(1e5); }

// A ggx r = 0.1 sphere (glossy_sun's chrome) under a 512 x 256 sky whose sun holds the light: the
// lobe is 2.9 env texels wide, EnvMis (env_product_tables.cpp, kMinProductLobeInEnvTexels).
std::shared_ptr<scene::Scene> chromeUnderSun() {
    scene::Material m;
    m.id = 1;
    m.name = "chrome";
    m.brdf = "ggx";
    m.roughness = 0.1f;
    m.baseColor = glm::vec3(0.95f);
    auto s = makeFurnaceScene(m, glm::vec3(1.0f), 32, 16);
    s->lighting.environment =
        makeSunSkyEnvironment(512, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e5);
    return s;
}

util::ImageRGB render(const std::shared_ptr<scene::Scene>& scene, SamplerKind kind, DeviceChoice device) {
    RenderOptions o;
    o.width = 24;
    o.height = 24;
    o.bounces = 3;
    o.seed = 5;
    o.sampler = kind;
    o.device = device;
    o.validation = true;
    auto integrator = makeTestIntegrator(scene, o);
    if (!integrator) {
        ADD_FAILURE() << integrator.error().message();
        return {};
    }
    for (int i = 0; i < 3; ++i) {
        auto status = (*integrator)->renderPass();
        EXPECT_TRUE(status.ok()) << status.error().message();
    }
    auto img = (*integrator)->image();
    EXPECT_TRUE(img.ok());
    return img ? *img : util::ImageRGB();
}

void expectSame(const util::ImageRGB& a, const util::ImageRGB& b) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    ASSERT_FALSE(a.pixels.empty());
    double sum = 0.0;
    size_t differ = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        sum += a.pixels[i].g;
        differ += a.pixels[i] != b.pixels[i] ? 1u : 0u;
    }
    EXPECT_GT(sum, 0.0) << "the sky lights the sphere";
    EXPECT_EQ(differ, 0u);
}

TEST(WaveletEnvMisPolicy, AllEnvMisSceneRendersAsMisOnTheCpu) {
    const auto scene = lambertUnderSun();
    expectSame(render(scene, SamplerKind::Wavelet, DeviceChoice::Cpu),
               render(scene, SamplerKind::Mis, DeviceChoice::Cpu));
}

TEST(WaveletEnvMisPolicy, AllEnvMisSceneRendersAsMisOnVulkanWithoutTheProductCode) {
    const auto scene = lambertUnderSun();
    expectSame(render(scene, SamplerKind::Wavelet, DeviceChoice::Vulkan),
               render(scene, SamplerKind::Mis, DeviceChoice::Vulkan));
}

// A mirror lobe 2-4 env texels wide under a sun (glossy_sun's chrome) renders as `mis`, and its
// kernel has no product code (docs/performance.md "Sun-lit fireflies of the wavelet sampler").
TEST(WaveletEnvMisPolicy, ChromeUnderASunRendersAsMisOnTheCpu) {
    const auto scene = chromeUnderSun();
    const scene::Material& chrome = scene->materials.front();
    ASSERT_EQ(chooseProductPolicy(*plugins::findBrdf("ggx"),
                                  plugins::BrdfParams(chrome.baseColor, chrome.roughness),
                                  SamplerEnvironment::build(scene->lighting.environment))
                  .mode,
              ProductMode::EnvMis);
    expectSame(render(scene, SamplerKind::Wavelet, DeviceChoice::Cpu),
               render(scene, SamplerKind::Mis, DeviceChoice::Cpu));
}

TEST(WaveletEnvMisPolicy, ChromeUnderASunRendersAsMisOnVulkan) {
    const auto scene = chromeUnderSun();
    expectSame(render(scene, SamplerKind::Wavelet, DeviceChoice::Vulkan),
               render(scene, SamplerKind::Mis, DeviceChoice::Vulkan));
}

// Under a soft sky the Lambert lobe is EnvMis too (round 5): the same estimator as `mis`.
TEST(WaveletEnvMisPolicy, LambertUnderASoftSkyRendersAsMisOnTheCpu) {
    const auto scene = lambertUnderSky(1.0);
    expectSame(render(scene, SamplerKind::Wavelet, DeviceChoice::Cpu),
               render(scene, SamplerKind::Mis, DeviceChoice::Cpu));
}

TEST(WaveletEnvMisPolicy, LambertUnderASoftSkyRendersAsMisOnVulkan) {
    const auto scene = lambertUnderSky(1.0);
    expectSame(render(scene, SamplerKind::Wavelet, DeviceChoice::Vulkan),
               render(scene, SamplerKind::Mis, DeviceChoice::Vulkan));
}

// An edit that brings a product into a kernel compiled without the code answers Unsupported with
// no file: the contract RenderSession recreates the tracer on (render_session.cpp), as for a BRDF
// plugin the kernel lacks.
TEST(WaveletEnvMisPolicy, AnEditThatNeedsTheProductCodeAsksForANewTracer) {
    // A ggx r = 0.2 sphere under a constant env: the env is far wider than the mirror lobe, so the
    // policy is EnvMis and the kernel is compiled without the product code (with ggx's twin).
    scene::Material m;
    m.id = 1;
    m.name = "gold";
    m.brdf = "ggx";
    m.roughness = 0.2f;
    m.baseColor = glm::vec3(0.9f);
    auto scene = makeFurnaceScene(m, glm::vec3(1.0f), 32, 16);
    auto flat = std::make_shared<util::ImageRGB>(256, 128, glm::vec3(1.0f));
    scene->lighting.environment.image = flat;
    const plugins::BrdfParams params(m.baseColor, m.roughness);
    ASSERT_EQ(chooseProductPolicy(*plugins::findBrdf("ggx"), params,
                                  SamplerEnvironment::build(scene->lighting.environment))
                  .mode,
              ProductMode::EnvMis);
    RenderOptions o;
    o.width = 16;
    o.height = 16;
    o.bounces = 2;
    o.sampler = SamplerKind::Wavelet;
    o.device = DeviceChoice::Vulkan;
    o.validation = true;
    auto gpu = makeTestIntegrator(scene, o);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    // A sky whose 13-degree sun (~0.05 sr, 10^4 x the sky) holds the light: env and lobe (0.02
    // sr) of comparable extent, the mirror lobe's product pays (same plugin: only the product
    // code is missing). (A one-texel sun would sit inside the lobe: EnvMis again.)
    auto edited = std::make_shared<scene::Scene>(*scene);
    edited->lighting.environment =
        makeSunSkyEnvironment(256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e4, 13.0);
    ASSERT_EQ(chooseProductPolicy(*plugins::findBrdf("ggx"), params,
                                  SamplerEnvironment::build(edited->lighting.environment))
                  .mode,
              ProductMode::Product);
    const auto status =
        (*gpu)->setScene(edited, std::make_shared<const scene::Bvh>(scene::buildBvh(*edited)));
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().kind, util::ErrorKind::Unsupported);
    EXPECT_TRUE(status.error().file.empty());
}

} // namespace
} // namespace wavelit::render
