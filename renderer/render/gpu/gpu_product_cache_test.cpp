// The per-pixel cache of the camera vertex's `wavelet` product (issue 12, docs/performance.md
// "Wavelet pass cost, round 4"; shaders/sampling/product_cache.glsl, product_cache.h). Built in
// the first pass after a reset from the pixel centre's hit and drawn from by later passes, it
// must (1) keep the estimator unbiased — the cached-product render's mean equals `bsdf`'s per
// block, on the Vulkan tracer and on its CPU twin, which caches the same pixels' centre-hit
// mixtures (cpu_camera_nee.cpp), and the two agree with each other — and (2) be rebuilt after
// any scene or camera change: the image after setScene equals bit for bit a fresh tracer's on
// the edited scene; (3) be kept across an edit of lights only (applyChanges), the image again a
// fresh tracer's bit for bit, and of the env's intensity (the tables are built at intensity 1).
#include "render/gpu/gpu_path_tracer_impl.h"
#include "render/reference/cpu_path_tracer.h"
#include "render/session/integrator_factory.h"
#include "render/sampling/product/env_product_tables.h"
#include "render/testing/pass_block_statistics.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/sampler_test_envs.h"
#include "render/testing/test_integrator.h"
#include "scene/bvh.h"
#include "scene/change_set.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace wavelit::render {
namespace {

constexpr int kSize = 24;
constexpr int kBlock = 8;

// A glossy GGX sphere (r = 0.3: policy Product, a per-hit 16^2 product on the GPU) under a sky
// whose 6-degree sun holds most of the light, bright enough that `bsdf` finds it through the lobe
// often (a converging reference) and compact enough that the product pays (not EnvMis).
std::shared_ptr<scene::Scene> glossyUnderSun(float cameraX) {
    scene::Material m;
    m.id = 1;
    m.name = "glossy";
    m.brdf = "ggx";
    m.roughness = 0.3f;
    m.baseColor = glm::vec3(0.9f, 0.7f, 0.4f);
    auto s = makeFurnaceScene(m, glm::vec3(1.0f), 48, 24);
    s->lighting.environment =
        makeSunSkyEnvironment(128, glm::normalize(glm::vec3(0.2f, 0.5f, 0.8f)), 300.0, 6.0);
    s->camera.position = glm::vec3(cameraX, 0.0f, 4.0f);
    return s;
}

RenderOptions testOptions(SamplerKind kind, DeviceChoice device, int bounces = 2) {
    RenderOptions o;
    o.width = kSize;
    o.height = kSize;
    o.bounces = bounces;
    o.seed = 7;
    o.sampler = kind;
    o.device = device;
    o.validation = true;
    return o;
}

std::unique_ptr<Integrator> makeTracer(const std::shared_ptr<scene::Scene>& scene,
                                       SamplerKind kind, DeviceChoice device, int bounces = 2) {
    auto integrator = makeTestIntegrator(scene, testOptions(kind, device, bounces));
    EXPECT_TRUE(integrator.ok()) << integrator.error().message();
    return integrator ? std::move(integrator.value()) : nullptr;
}

// Pixels whose values differ at all between the two tracers' images.
size_t differingPixels(Integrator& a, Integrator& b) {
    auto x = a.image();
    auto y = b.image();
    EXPECT_TRUE(x.ok() && y.ok());
    if (!x.ok() || !y.ok())
        return ~size_t(0);
    size_t differ = 0;
    for (size_t i = 0; i < x->pixels.size(); ++i)
        differ += x->pixels[i] != y->pixels[i] ? 1u : 0u;
    return differ;
}

TEST(GpuProductCache, TheSceneDrawsFromAPerHitProduct) {
    const auto scene = glossyUnderSun(0.0f);
    auto cpu = makeTracer(scene, SamplerKind::Wavelet, DeviceChoice::Cpu);
    ASSERT_TRUE(cpu);
    ASSERT_TRUE(cpu->samplerTables());
    const MaterialProductTables* t = cpu->samplerTables()->productTables(0);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->policy().mode, ProductMode::Product) << t->describe();
}

TEST(GpuProductCache, CachedProductRenderMeanEqualsBsdfPerBlock) {
    const auto scene = glossyUnderSun(0.0f);
    auto bsdf = makeTracer(scene, SamplerKind::Bsdf, DeviceChoice::Cpu);
    auto gpu = makeTracer(scene, SamplerKind::Wavelet, DeviceChoice::Vulkan);
    auto cpu = makeTracer(scene, SamplerKind::Wavelet, DeviceChoice::Cpu);
    ASSERT_TRUE(bsdf && gpu && cpu);
    const BlockStatistics reference = passBlockStatistics(*bsdf, 512, kSize, kBlock);
    const BlockStatistics gpuStats = passBlockStatistics(*gpu, 96, kSize, kBlock);
    const BlockStatistics cpuStats = passBlockStatistics(*cpu, 96, kSize, kBlock);
    expectSameBlockMeans(gpuStats, reference, "vulkan wavelet (cached) vs bsdf");
    expectSameBlockMeans(cpuStats, reference, "cpu wavelet (cached twin) vs bsdf");
    // Both caches' estimators against each other, block by block (the CPU twin caches the same
    // pixels' centre-hit mixtures: cpu_camera_nee.cpp).
    expectSameBlockMeans(cpuStats, gpuStats, "cpu wavelet (cached) vs vulkan wavelet (cached)");
    EXPECT_EQ(gpu->validationMessageCount(), 0);
    auto* tracer = dynamic_cast<gpu_tracer::GpuPathTracer*>(gpu.get());
    ASSERT_NE(tracer, nullptr);
    EXPECT_EQ(tracer->productCacheBuilds(), 1u) << "built once, read by the other 95 passes";
    auto* cpuTracer = dynamic_cast<CpuPathTracer*>(cpu.get());
    ASSERT_NE(cpuTracer, nullptr);
    EXPECT_EQ(cpuTracer->productCacheBuilds(), 1u) << "built once, read by the other 95 passes";
    EXPECT_GT(cpuTracer->productCacheEntries(), 0u);
}

TEST(GpuProductCache, RebuiltAfterASceneOrCameraChange) {
    const auto before = glossyUnderSun(0.0f);
    auto edited = glossyUnderSun(0.4f); // the camera moved: every pixel's centre hit moves
    edited->materials[0].roughness = 0.35f;
    auto gpu = makeTracer(before, SamplerKind::Wavelet, DeviceChoice::Vulkan);
    ASSERT_TRUE(gpu);
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(gpu->renderPass().ok());
    ASSERT_TRUE(gpu->setScene(edited, std::make_shared<const scene::Bvh>(scene::buildBvh(*edited)))
                    .ok());
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(gpu->renderPass().ok());
    auto fresh = makeTracer(edited, SamplerKind::Wavelet, DeviceChoice::Vulkan);
    ASSERT_TRUE(fresh);
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(fresh->renderPass().ok());
    auto a = gpu->image();
    ASSERT_TRUE(a.ok());
    double sum = 0.0;
    for (const glm::vec3& p : a->pixels)
        sum += p.g;
    EXPECT_GT(sum, 0.0);
    EXPECT_EQ(differingPixels(*gpu, *fresh), 0u)
        << "a stale cache (the old camera's centre hits) changes the draws";
    auto* tracer = dynamic_cast<gpu_tracer::GpuPathTracer*>(gpu.get());
    ASSERT_NE(tracer, nullptr);
    EXPECT_EQ(tracer->productCacheBuilds(), 2u);
    EXPECT_GT(tracer->productCacheBytes(), 0u);
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

// The first pass lays the cache out on the CPU (a centre ray a pixel: ~0.2 s at 1600 x 1000 on
// 2 cores) in bands of rows between interrupt checks, so that the editor's quit and requests do
// not wait for it: an interrupt stops the layout between two bands, the next call resumes it
// (one layout in all), and the image is the uninterrupted one bit for bit.
TEST(GpuProductCache, AnInterruptedLayoutResumesWhereItStopped) {
    const auto scene = glossyUnderSun(0.0f);
    RenderOptions o = testOptions(SamplerKind::Wavelet, DeviceChoice::Vulkan);
    o.width = 256;
    o.height = 3 * gpu_tracer::kProductCacheLayoutBandPixels / o.width - 16; // three bands, the last shorter
    auto plain = makeTestIntegrator(scene, o);
    auto pieced = makeTestIntegrator(scene, o);
    ASSERT_TRUE(plain.ok() && pieced.ok());
    ASSERT_TRUE((*plain)->renderPass().ok());
    auto* tracer = dynamic_cast<gpu_tracer::GpuPathTracer*>(pieced->get());
    ASSERT_NE(tracer, nullptr);
    int polls = 0;
    tracer->setInterruptCheck([&] { return ++polls % 2 == 0; }); // every other poll fires
    // Poll 1 lets the first band run, poll 2 stops the layout; likewise the second band.
    for (int call = 1; call <= 2; ++call) {
        ASSERT_TRUE(tracer->renderPass().ok());
        EXPECT_EQ(polls, 2 * call);
        EXPECT_EQ(tracer->productCacheBuilds(), 0u) << "call " << call << ": the layout is unfinished";
    }
    ASSERT_TRUE(tracer->renderPass().ok()); // the third band, then the first piece's poll fires
    EXPECT_EQ(tracer->productCacheBuilds(), 1u);
    EXPECT_EQ(tracer->samplesPerPixel(), 0);
    while (tracer->samplesPerPixel() == 0 && polls < 1000)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 1u);
    EXPECT_EQ(differingPixels(*tracer, **plain), 0u);
    EXPECT_EQ(tracer->validationMessageCount(), 0);
}

// One edit through applyChanges after two passes: the cache is kept (one build in all) and the
// image equals a fresh tracer's on the edited scene.
void expectCacheKeptAcross(scene::EntityRef ref, const std::string& property,
                           scene::PropertyValue value) {
    auto before = glossyUnderSun(0.0f);
    scene::Light lamp;
    lamp.id = 7;
    lamp.name = "lamp";
    lamp.position = glm::vec3(1.5f, 2.0f, 2.0f);
    lamp.intensity = 40.0f;
    before->lighting.lights.push_back(lamp);
    const auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*before));
    auto created =
        createGpuPathTracer(before, bvh, testOptions(SamplerKind::Wavelet, DeviceChoice::Vulkan));
    ASSERT_TRUE(created.ok()) << created.error().message();
    std::unique_ptr<Integrator> gpu = std::move(created.value());
    for (int i = 0; i < 2; ++i)
        ASSERT_TRUE(gpu->renderPass().ok());
    scene::ChangeSet changes;
    ASSERT_TRUE(changes.setProperty(*before, ref, property, value).ok());
    auto after = std::make_shared<scene::Scene>(*before);
    ASSERT_TRUE(changes.apply(*after).ok());
    // The same BVH object, as the session hands it over when no geometry changed.
    auto* tracer = dynamic_cast<gpu_tracer::GpuPathTracer*>(gpu.get());
    ASSERT_NE(tracer, nullptr);
    ASSERT_TRUE(gpu->applyChanges(after, bvh, changes).ok());
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(gpu->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 1u) << "the " << property << " edit rebuilt the cache";
    auto fresh = makeTracer(after, SamplerKind::Wavelet, DeviceChoice::Vulkan);
    ASSERT_TRUE(fresh);
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(fresh->renderPass().ok());
    EXPECT_EQ(differingPixels(*gpu, *fresh), 0u)
        << "the kept cache draws differently from a fresh tracer's";
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

TEST(GpuProductCache, KeptAcrossALightOnlyEdit) {
    expectCacheKeptAcross({scene::EntityKind::Light, 7}, "intensity", 90.0f);
}

// The sampler tables are built at intensity 1 (tablesEnvironment): an env intensity edit keeps
// them, and with them the cache.
TEST(GpuProductCache, KeptAcrossAnEnvironmentIntensityEdit) {
    expectCacheKeptAcross({scene::EntityKind::Environment, scene::kInvalidId}, "intensity", 0.3f);
}

} // namespace
} // namespace wavelit::render
