// SamplerTablesCache (issue 6; architecture.md §5 change sets, §7): each edit rebuilds exactly the
// tables it invalidates, judged twice — by the cache's counters and by pointer identity of the
// shared SamplerEnvironment / MaterialProductTables — and whatever is rebuilt or reused is the
// same in content as a fresh build (environment edits: sampler_tables_cache_environment_test.cpp).
// Then the CPU tracer through RenderSession: an object move swaps the scene without touching the
// tables, and the image follows the move.
#include "render/sampling/sampler_tables_cache.h"

#include "render/sampling/sampler_tables_cache_test_support.h"
#include "render/session/render_session.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/sampler_test_envs.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace wavelit::render {

// The support header's test scene (here: the render test executable's *_test.cpp files may use
// render/testing/).
namespace sampler_tables_test {

scene::Scene testScene() {
    scene::Material ggx;
    ggx.name = "glossy";
    ggx.brdf = "ggx";
    ggx.roughness = 0.35f;
    ggx.baseColor = glm::vec3(0.9f, 0.7f, 0.5f);
    scene::Scene s = *makeFurnaceScene(ggx, glm::vec3(1.0f), 32, 16);
    scene::Material lambert;
    lambert.id = 3;
    lambert.name = "matte";
    lambert.brdf = "lambert";
    s.materials.push_back(lambert);
    scene::Object second = s.objects[0];
    second.id = 4;
    second.name = "matte sphere";
    second.materialId = lambert.id;
    second.transform.translation = glm::vec3(1.2f, 0.0f, -1.0f);
    second.transform.scale = glm::vec3(0.5f);
    s.objects[0].transform.scale = glm::vec3(0.6f);
    s.objects.push_back(second);
    s.lighting.environment = makeSunSkyEnvironment(64, glm::vec3(0.3f, 0.8f, 0.5f), 200.0);
    return s;
}

} // namespace sampler_tables_test

namespace {

using namespace sampler_tables_test;

TEST(SamplerTablesCache, FirstUpdateBuildsTheEnvAndOneProductTablePerUsedMaterial) {
    const scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto t = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(t.ok()) << t.error().message();
    expectCounts(cache.rebuilds(), {1, 2, 0, 0});
    EXPECT_EQ(t->samplerIndexOfMaterial, (std::vector<int>{0, 1, -1})); // default: unused
    ASSERT_EQ(t->tables->materialCount(), 2u);
    EXPECT_EQ(product(*t, kGgx)->policy().mode, ProductMode::Product);
    EXPECT_GT(product(*t, kGgx)->policy().binLevel, 0); // windowed, so rebuilding is not trivial
    EXPECT_FALSE(t->tables->environmentReused());
    std::printf("[tables] %s", t->tables->report().c_str());
}

TEST(SamplerTablesCache, ObjectMoveRebuildsNothingAndKeepsTheSameTables) {
    scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto before = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(before.ok());
    scene.objects[1].transform.translation += glm::vec3(-0.3f, 0.4f, 0.2f);
    scene.objects[0].transform.rotationDeg = glm::vec3(10.0f, 20.0f, 30.0f);
    auto after = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(after.ok());
    expectCounts(cache.rebuilds(), {1, 2, 1, 2});
    EXPECT_EQ(after->tables, before->tables); // nothing changed: the very same tables
    EXPECT_EQ(&after->tables->environment(), &before->tables->environment());
    EXPECT_EQ(product(*after, kGgx), product(*before, kGgx));
    EXPECT_EQ(product(*after, kLambert), product(*before, kLambert));
}

TEST(SamplerTablesCache, RoughnessEditRebuildsExactlyThatMaterial) {
    scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto before = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(before.ok());
    scene.materials[kGgx].roughness = 0.5f;
    auto after = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(after.ok());
    expectCounts(cache.rebuilds(), {1, 3, 1, 1});
    EXPECT_EQ(&after->tables->environment(), &before->tables->environment());
    EXPECT_NE(product(*after, kGgx), product(*before, kGgx));
    EXPECT_EQ(product(*after, kLambert), product(*before, kLambert));
    EXPECT_TRUE(after->tables->environmentReused());
    const auto samplerIndex = [&](size_t m) { return size_t(after->samplerIndexOfMaterial[m]); };
    EXPECT_FALSE(after->tables->productTablesReused(samplerIndex(kGgx)));
    EXPECT_TRUE(after->tables->productTablesReused(samplerIndex(kLambert)));
    expectSameAsFreshBuild(scene, *after);
}

TEST(SamplerTablesCache, AddingAnUnusedMaterialBuildsNothing) {
    scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto before = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(before.ok());
    scene::Material extra;
    extra.id = scene.nextId();
    extra.name = "spare";
    extra.brdf = "ggx";
    extra.roughness = 0.1f;
    scene.materials.push_back(extra);
    auto after = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(after.ok());
    expectCounts(cache.rebuilds(), {1, 2, 1, 2});
    EXPECT_EQ(after->samplerIndexOfMaterial, (std::vector<int>{0, 1, -1, -1}));
    EXPECT_EQ(after->tables, before->tables);
}

TEST(SamplerTablesCache, MaterialBecomingUsedBuildsOnlyIt) {
    scene::Scene scene = testScene();
    scene::Material extra;
    extra.id = scene.nextId();
    extra.name = "spare";
    extra.brdf = "ggx";
    extra.roughness = 0.6f;
    scene.materials.push_back(extra);
    SamplerTablesCache cache;
    auto before = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(before.ok());
    expectCounts(cache.rebuilds(), {1, 2, 0, 0});
    scene::Object third = scene.objects[1];
    third.id = scene.nextId();
    third.materialId = extra.id;
    third.transform.translation = glm::vec3(-1.2f, 0.0f, -1.0f);
    scene.objects.push_back(third);
    auto after = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(after.ok());
    expectCounts(cache.rebuilds(), {1, 3, 1, 2});
    EXPECT_EQ(after->samplerIndexOfMaterial, (std::vector<int>{0, 1, 2, -1}));
    EXPECT_EQ(product(*after, kGgx), product(*before, kGgx));
    EXPECT_EQ(product(*after, kLambert), product(*before, kLambert));
    EXPECT_NE(product(*after, 2), nullptr);
    expectSameAsFreshBuild(scene, *after);
}

TEST(SamplerTablesCache, DefaultMaterialGetsTablesOnlyWhenAnObjectFallsBackToIt) {
    scene::Scene scene = testScene();
    scene.objects[1].materialId = 999; // unknown id: the default material (bvh.cpp)
    SamplerTablesCache cache;
    auto t = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(t->samplerIndexOfMaterial, (std::vector<int>{0, -1, 1}));
    EXPECT_EQ(t->tables->material(1).brdf, plugins::findBrdf(scene::Material{}.brdf));
    EXPECT_NE(product(*t, kDefault), nullptr);
}

TEST(SamplerTablesCache, BsdfKindNeedsNoTables) {
    const scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto t = cache.update(scene, SamplerKind::Bsdf);
    ASSERT_TRUE(t.ok());
    EXPECT_EQ(t->tables, nullptr);
    EXPECT_EQ(t->samplerIndexOfMaterial, (std::vector<int>{-1, -1, -1}));
    expectCounts(cache.rebuilds(), {0, 0, 0, 0});
}

TEST(SamplerTablesCache, KindsWithoutProductsBuildTheEnvOnlyAndShareIt) {
    const scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto mis = cache.update(scene, SamplerKind::Mis);
    ASSERT_TRUE(mis.ok());
    expectCounts(cache.rebuilds(), {1, 0, 0, 0});
    EXPECT_EQ(mis->tables->productTables(0), nullptr);
    // Switching to wavelet keeps the env (it does not depend on the kind) and adds products.
    auto wavelet = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(wavelet.ok());
    expectCounts(cache.rebuilds(), {1, 2, 1, 0});
    EXPECT_EQ(&wavelet->tables->environment(), &mis->tables->environment());
}

TEST(SamplerTablesCache, UnknownBrdfIsUnsupportedAndNamesTheMaterial) {
    scene::Scene scene = testScene();
    scene.materials[kLambert].brdf = "velvet";
    SamplerTablesCache cache;
    auto t = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().kind, util::ErrorKind::Unsupported);
    EXPECT_EQ(t.error().where, "/materials/1/brdf");
    EXPECT_NE(t.error().message().find("matte"), std::string::npos) << t.error().message();
    expectCounts(cache.rebuilds(), {0, 0, 0, 0});
}

RenderOptions cpuWavelet() {
    RenderOptions o;
    o.width = o.height = 24;
    o.bounces = 1;
    o.seed = 7;
    o.device = DeviceChoice::Cpu;
    o.sampler = SamplerKind::Wavelet;
    return o;
}

double meanLuminance(RenderSession& session, int passes) {
    for (int i = 0; i < passes; ++i)
        EXPECT_TRUE(session.renderPass().ok());
    auto img = session.image();
    EXPECT_TRUE(img.ok());
    double sum = 0.0;
    for (const glm::vec3& p : img->pixels)
        sum += util::luminance(p);
    return sum / double(img->pixels.size());
}

TEST(SamplerTablesCache, CpuTracerObjectMoveKeepsTheTablesAndChangesTheImage) {
    scene::Scene scene = testScene();
    auto session = RenderSession::create(scene, cpuWavelet());
    ASSERT_TRUE(session.ok()) << session.error().message();
    const double before = meanLuminance(**session, 2);
    const RenderStats first = (*session)->stats();
    ASSERT_NE(first.samplerTables, nullptr);
    expectCounts(first.samplerRebuilds, {1, 2, 0, 0});
    auto firstImage = (*session)->image();

    // Bring the matte sphere in front of the glossy one: the image must change, the tables not.
    scene.objects[1].transform.translation = glm::vec3(0.0f, 0.0f, 1.5f);
    ASSERT_TRUE((*session)->setScene(scene).ok());
    EXPECT_EQ((*session)->samplesPerPixel(), 0);
    const double after = meanLuminance(**session, 2);
    const RenderStats second = (*session)->stats();
    EXPECT_EQ(second.samplerTables, first.samplerTables);
    expectCounts(second.samplerRebuilds, {1, 2, 1, 2}); // the same integrator: it swapped scenes
    auto secondImage = (*session)->image();
    int changed = 0;
    for (size_t i = 0; i < firstImage->pixels.size(); ++i)
        changed += firstImage->pixels[i] != secondImage->pixels[i] ? 1 : 0;
    std::printf("[tables] object move: mean %.4f -> %.4f, %d of %zu pixels changed\n", before,
                after, changed, firstImage->pixels.size());
    // The sphere now covers a good part of the frame (not just noise from a different path).
    EXPECT_GT(changed, int(firstImage->pixels.size() / 8));

    // An env rotation through the same session turns the env tables and keeps both product tables.
    scene.lighting.environment.rotationDeg = 90.0f;
    ASSERT_TRUE((*session)->setScene(scene).ok());
    const RenderStats third = (*session)->stats();
    EXPECT_NE(third.samplerTables, first.samplerTables);
    expectCounts(third.samplerRebuilds, {1, 2, 1, 4});
    EXPECT_EQ(third.samplerRebuilds.environmentRotations, 1);
}

TEST(SamplerTablesCache, CpuTracerRejectsAnUnknownBrdfOnSetSceneAndKeepsItsScene) {
    scene::Scene scene = testScene();
    auto session = RenderSession::create(scene, cpuWavelet());
    ASSERT_TRUE(session.ok());
    const auto tables = (*session)->stats().samplerTables;
    scene.materials[kGgx].brdf = "velvet";
    auto status = (*session)->setScene(scene);
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().where, "/materials/0/brdf");
    EXPECT_EQ((*session)->stats().samplerTables, tables);
}

} // namespace
} // namespace wavelit::render
