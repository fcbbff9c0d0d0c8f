// The CPU tracer's per-pixel cache of `wavelet`'s camera-vertex mixture (issue 12,
// cpu_camera_nee.cpp; the Vulkan tracer's twin: render/gpu/gpu_product_cache_test.cpp). Built in
// the first pass after a reset from the pixel centre's hit and read by later passes, it must
// (1) be the mixture a path would build for itself — a cached path equals bit for bit the same
// path of a tracer without a cache; (2) keep the estimator unbiased over many passes — per block
// the wavelet render's mean equals a converged `bsdf` reference's, also when a memory budget
// leaves a hashed subset of the pixels out; (3) be built once, and rebuilt after a material or
// environment edit (or a reset): the image after the edit equals bit for bit a fresh tracer's;
// (4) be kept across an edit of lights or of the env's intensity (the entries depend on camera,
// geometry, materials and tables, and the tables are built at intensity 1), again equal bit for
// bit to a fresh tracer's image.
#include "render/reference/cpu_path_tracer.h"

#include "render/sampling/product/env_product_tables.h"
#include "render/testing/pass_block_statistics.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/sampler_test_envs.h"
#include "scene/bvh.h"
#include "scene/change_set.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace wavelit::render {
namespace {

constexpr int kSize = 24;
constexpr int kBlock = 8;

// A glossy GGX sphere (r = 0.3: policy Product, a per-hit product) filling ~70% of the image
// under a sky whose 6-degree sun holds most of the light (the scene of the GPU cache's test): the
// sphere's pixels get entries, the background's none, and its silhouette's paths whose centre
// missed take `mis`'s technique.
std::shared_ptr<scene::Scene> glossyUnderSun() {
    scene::Material m;
    m.id = 1;
    m.name = "glossy";
    m.brdf = "ggx";
    m.roughness = 0.3f;
    m.baseColor = glm::vec3(0.9f, 0.7f, 0.4f);
    auto s = makeFurnaceScene(m, glm::vec3(1.0f), 48, 24);
    s->lighting.environment =
        makeSunSkyEnvironment(128, glm::normalize(glm::vec3(0.2f, 0.5f, 0.8f)), 300.0, 6.0);
    return s;
}

std::unique_ptr<CpuPathTracer> makeTracer(const std::shared_ptr<const scene::Scene>& scene,
                                          SamplerKind kind,
                                          std::shared_ptr<const scene::Bvh> bvh = nullptr) {
    RenderOptions o;
    o.width = kSize;
    o.height = kSize;
    o.bounces = 2;
    o.seed = 7;
    o.sampler = kind;
    if (!bvh)
        bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto tracer = CpuPathTracer::create(scene, std::move(bvh), o, 2);
    EXPECT_TRUE(tracer.ok()) << tracer.error().message();
    return tracer ? std::move(tracer.value()) : nullptr;
}

// The image of `passes` passes of a fresh tracer on `scene`.
std::vector<glm::vec3> freshImage(const std::shared_ptr<const scene::Scene>& scene, int passes) {
    auto fresh = makeTracer(scene, SamplerKind::Wavelet);
    for (int i = 0; i < passes; ++i)
        EXPECT_TRUE(fresh->renderPass().ok());
    auto img = fresh->image();
    EXPECT_TRUE(img.ok());
    EXPECT_EQ(fresh->productCacheBuilds(), 1u);
    return img->pixels;
}

size_t differingPixels(CpuPathTracer& tracer, const std::vector<glm::vec3>& expected) {
    auto img = tracer.image();
    EXPECT_TRUE(img.ok());
    size_t differ = 0;
    for (size_t i = 0; i < expected.size(); ++i)
        differ += img->pixels[i] != expected[i] ? 1u : 0u;
    return differ;
}

TEST(CpuProductCache, TheSceneDrawsFromAPerHitProduct) {
    auto tracer = makeTracer(glossyUnderSun(), SamplerKind::Wavelet);
    ASSERT_TRUE(tracer && tracer->samplerTables());
    const MaterialProductTables* t = tracer->samplerTables()->productTables(0);
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->policy().mode, ProductMode::Product) << t->describe();
}

TEST(CpuProductCache, ACachedPathEqualsThePathThatBuildsItsOwnMixture) {
    const auto scene = glossyUnderSun();
    auto cached = makeTracer(scene, SamplerKind::Wavelet);
    auto uncached = makeTracer(scene, SamplerKind::Wavelet); // never renders: no cache
    ASSERT_TRUE(cached && uncached);
    EXPECT_EQ(cached->productCacheBuilds(), 0u);
    ASSERT_TRUE(cached->renderPass().ok());
    EXPECT_EQ(cached->productCacheBuilds(), 1u);
    // The sphere's pixels have an entry, the background's none.
    const size_t pixels = size_t(kSize * kSize);
    EXPECT_GT(cached->productCacheEntries(), pixels / 4);
    EXPECT_LT(cached->productCacheEntries(), pixels);
    EXPECT_EQ(cached->productCacheSkipped(), 0u);
    size_t differ = 0, lit = 0;
    for (int pass = 1; pass <= 3; ++pass)
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec3 a = cached->samplePixel(x, y, pass);
                const glm::vec3 b = uncached->samplePixel(x, y, pass);
                differ += a != b ? 1u : 0u;
                lit += a.g > 0.0f ? 1u : 0u;
            }
    EXPECT_GT(lit, pixels);
    EXPECT_EQ(differ, 0u) << "the cached mixture is not the one the path builds at its centre hit";
}

TEST(CpuProductCache, CachedRenderMeanEqualsBsdfPerBlock) {
    const auto scene = glossyUnderSun();
    auto bsdf = makeTracer(scene, SamplerKind::Bsdf);
    auto wavelet = makeTracer(scene, SamplerKind::Wavelet);
    auto budgeted = makeTracer(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(bsdf && wavelet && budgeted);
    const BlockStatistics reference = passBlockStatistics(*bsdf, 512, kSize, kBlock);
    const BlockStatistics cachedStats = passBlockStatistics(*wavelet, 96, kSize, kBlock);
    // A budget for about half the entries (the full cache's size: its pixels' index words and
    // the entries): a hashed half of the sphere's pixels use `mis`'s technique at their camera
    // vertex.
    const uint64_t indexBytes = uint64_t(kSize * kSize) * 4u;
    const uint64_t fullBytes = wavelet->timings().productCacheBytes;
    ASSERT_GT(fullBytes, indexBytes);
    budgeted->setProductCacheBudget(indexBytes + (fullBytes - indexBytes) / 2u);
    const BlockStatistics budgetedStats = passBlockStatistics(*budgeted, 96, kSize, kBlock);
    expectSameBlockMeans(cachedStats, reference, "cpu wavelet (cached) vs bsdf");
    expectSameBlockMeans(budgetedStats, reference, "cpu wavelet (half cached) vs bsdf");
    EXPECT_EQ(wavelet->productCacheBuilds(), 1u) << "built once, read by the other 95 passes";
    EXPECT_EQ(budgeted->productCacheBuilds(), 1u);
    EXPECT_GT(budgeted->productCacheSkipped(), 0u);
    EXPECT_EQ(budgeted->productCacheEntries() + budgeted->productCacheSkipped(),
              wavelet->productCacheEntries());
}

TEST(CpuProductCache, RebuiltAfterAMaterialOrEnvironmentEditOrAReset) {
    const auto before = glossyUnderSun();
    auto tracer = makeTracer(before, SamplerKind::Wavelet);
    ASSERT_TRUE(tracer);
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 1u);

    // A material edit: the entries hold the old roughness's products.
    auto rougher = std::make_shared<scene::Scene>(*before);
    rougher->materials[0].roughness = 0.35f;
    ASSERT_TRUE(tracer->setScene(rougher, std::make_shared<const scene::Bvh>(
                                              scene::buildBvh(*rougher)))
                    .ok());
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 2u);
    EXPECT_EQ(differingPixels(*tracer, freshImage(rougher, 3)), 0u)
        << "a stale cache (the old material's products) changes the draws";

    // An environment edit: the entries hold the old sky's products and shares.
    auto rotated = std::make_shared<scene::Scene>(*rougher);
    rotated->lighting.environment.rotationDeg += 40.0f;
    ASSERT_TRUE(tracer->setScene(rotated, std::make_shared<const scene::Bvh>(
                                              scene::buildBvh(*rotated)))
                    .ok());
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 3u);
    const std::vector<glm::vec3> rotatedImage = freshImage(rotated, 3);
    EXPECT_EQ(differingPixels(*tracer, rotatedImage), 0u)
        << "a stale cache (the old environment's products) changes the draws";

    // A reset alone rebuilds it (the GPU's rule), and the image starts over identically.
    tracer->resetAccumulation();
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 4u);
    EXPECT_EQ(differingPixels(*tracer, rotatedImage), 0u);
}

// applyChanges with the change set of one property edit (no geometry: the same BVH object, as
// the session hands it over); the scene after it.
std::shared_ptr<const scene::Scene> applyEdit(CpuPathTracer& tracer, const scene::Scene& before,
                                              const std::shared_ptr<const scene::Bvh>& bvh,
                                              scene::EntityRef ref, const std::string& property,
                                              scene::PropertyValue value) {
    scene::ChangeSet changes;
    EXPECT_TRUE(changes.setProperty(before, ref, property, value).ok());
    auto after = std::make_shared<scene::Scene>(before);
    EXPECT_TRUE(changes.apply(*after).ok());
    EXPECT_TRUE(tracer.applyChanges(after, bvh, changes).ok());
    return after;
}

TEST(CpuProductCache, KeptAcrossALightOrEnvIntensityEditAndRebuiltAfterATintOrCameraEdit) {
    auto lit = glossyUnderSun();
    scene::Light lamp;
    lamp.id = 7;
    lamp.name = "lamp";
    lamp.type = scene::LightType::Point;
    lamp.position = glm::vec3(1.5f, 2.0f, 2.0f);
    lamp.intensity = 40.0f;
    lit->lighting.lights.push_back(lamp);
    const auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*lit));
    auto tracer = makeTracer(lit, SamplerKind::Wavelet, bvh);
    ASSERT_TRUE(tracer);
    for (int i = 0; i < 2; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    ASSERT_EQ(tracer->productCacheBuilds(), 1u);

    const scene::EntityRef lampRef{scene::EntityKind::Light, 7};
    const auto brighter = applyEdit(*tracer, *lit, bvh, lampRef, "intensity", 90.0f);
    const auto moved =
        applyEdit(*tracer, *brighter, bvh, lampRef, "position", glm::vec3(-1.0f, 2.5f, 1.0f));
    // The sampler tables are built at intensity 1 (tablesEnvironment): kept, and the cache too.
    const scene::EntityRef env{scene::EntityKind::Environment, scene::kInvalidId};
    const auto dimmer = applyEdit(*tracer, *moved, bvh, env, "intensity", 0.3f);
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 1u)
        << "a light or env intensity edit rebuilt the cache";
    EXPECT_EQ(differingPixels(*tracer, freshImage(dimmer, 3)), 0u)
        << "the kept cache draws differently from a fresh tracer's";

    // A tint changes the luminance the tables follow: new tables, a new cache.
    const auto tinted = applyEdit(*tracer, *dimmer, bvh, env, "tint", glm::vec3(1.0f, 0.6f, 0.3f));
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 2u) << "a tint edit must rebuild the cache";
    EXPECT_EQ(differingPixels(*tracer, freshImage(tinted, 3)), 0u);

    const scene::EntityRef camera{scene::EntityKind::Camera, scene::kInvalidId};
    const auto turned =
        applyEdit(*tracer, *tinted, bvh, camera, "position", glm::vec3(0.3f, 0.2f, 3.2f));
    for (int i = 0; i < 3; ++i)
        ASSERT_TRUE(tracer->renderPass().ok());
    EXPECT_EQ(tracer->productCacheBuilds(), 3u) << "a camera edit must rebuild the cache";
    EXPECT_EQ(differingPixels(*tracer, freshImage(turned, 3)), 0u);
}

TEST(CpuProductCache, OtherSamplersBuildNone) {
    const auto scene = glossyUnderSun();
    for (SamplerKind kind : {SamplerKind::Bsdf, SamplerKind::Mis, SamplerKind::Oracle}) {
        auto tracer = makeTracer(scene, kind);
        ASSERT_TRUE(tracer);
        ASSERT_TRUE(tracer->renderPass().ok());
        EXPECT_EQ(tracer->productCacheBuilds(), 0u) << samplerKindName(kind);
        EXPECT_EQ(tracer->productCacheEntries(), 0u);
    }
}

} // namespace
} // namespace wavelit::render
