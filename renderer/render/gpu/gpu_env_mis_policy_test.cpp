// The `wavelet` policy EnvMis (issue 12, docs/performance.md "Wavelet pass cost, round 3"): a
// scene whose every material has env and lobe of very different extent draws from no product.
// Its vertices use `mis`'s technique with the same random numbers, so a `wavelet` render equals
// the `mis` render bit for bit on both tracers, and the Vulkan kernel is compiled without the
// product code (it must still compile and run under validation).
#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/sampler_test_envs.h"
#include "render/testing/test_integrator.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace wavelit::render {
namespace {

// A Lambert sphere under a sky whose sun holds the light: the env's effective solid angle is far
// below the cosine lobe's, so the policy is EnvMis.
std::shared_ptr<scene::Scene> lambertUnderSun() {
    scene::Material m;
    m.id = 1;
    m.name = "matte";
    m.brdf = "lambert";
    m.baseColor = glm::vec3(0.7f);
    auto s = makeFurnaceScene(m, glm::vec3(1.0f), 32, 16);
    s->lighting.environment = makeSunSkyEnvironment(64, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e5);
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
    EXPECT_GT(sum, 0.0) << "the sun lights the sphere";
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

// An edit that brings a product into a kernel compiled without the code answers Unsupported with
// no file: the contract RenderSession recreates the tracer on (render_session.cpp), as for a BRDF
// plugin the kernel lacks.
TEST(WaveletEnvMisPolicy, AnEditThatNeedsTheProductCodeAsksForANewTracer) {
    const auto scene = lambertUnderSun();
    RenderOptions o;
    o.width = 16;
    o.height = 16;
    o.bounces = 2;
    o.sampler = SamplerKind::Wavelet;
    o.device = DeviceChoice::Vulkan;
    o.validation = true;
    auto gpu = makeTestIntegrator(scene, o);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    // The same sky with a sun no brighter than its mean: the env spreads over steradians, the
    // cosine lobe's product pays again (same plugin: only the product code is missing).
    auto soft = std::make_shared<scene::Scene>(*scene);
    soft->lighting.environment =
        makeSunSkyEnvironment(64, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1.0);
    const auto status =
        (*gpu)->setScene(soft, std::make_shared<const scene::Bvh>(scene::buildBvh(*soft)));
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().kind, util::ErrorKind::Unsupported);
    EXPECT_TRUE(status.error().file.empty());
}

} // namespace
} // namespace wavelit::render
