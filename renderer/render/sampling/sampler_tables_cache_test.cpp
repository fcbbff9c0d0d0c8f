// SamplerTablesCache (issue 6; architecture.md §5 change sets, §7): each edit rebuilds exactly the
// tables it invalidates, judged twice — by the cache's counters and by pointer identity of the
// shared SamplerEnvironment / MaterialProductTables — and whatever is rebuilt or reused is the
// same in content as a fresh build. Then the CPU tracer through RenderSession: an object move swaps
// the scene without touching the tables, and the image follows the move.
#include "render/sampling/sampler_tables_cache.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "render/session/render_session.h"
#include "render/testing/sampler_test_envs.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <regex>
#include <string>

namespace wavelit::render {
namespace {

// Indices of the test scene's materials (and the default one, unused) in Scene::materials order.
constexpr size_t kGgx = 0, kLambert = 1, kDefault = 2;

// Two spheres: a GGX one (roughness 0.35, where the product policy builds windowed bins: its lobe
// is 4.4 env texels wide, over the 4 below which the policy takes mis's technique) and a
// Lambert one, under a 64 x 32 sky with a sun (env level 6: a small but lit map).
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

struct Counts {
    int envBuilds, materialBuilds, envReuses, materialReuses;
};

void expectCounts(const SamplerTablesRebuilds& r, Counts c) {
    EXPECT_EQ(r.environmentBuilds, c.envBuilds);
    EXPECT_EQ(r.materialBuilds, c.materialBuilds);
    EXPECT_EQ(r.environmentReuses, c.envReuses);
    EXPECT_EQ(r.materialReuses, c.materialReuses);
}

// Product tables of scene material `m`: nullptr when it has none.
const MaterialProductTables* product(const SceneSamplerTables& t, size_t m) {
    const int i = t.samplerIndexOfMaterial.at(m);
    return i < 0 ? nullptr : t.tables->productTables(size_t(i));
}

// The report with build times and reuse marks removed: what a fresh build must reproduce.
std::string reportWithoutTimings(const DirectionSamplerTables& t) {
    static const std::regex timing(R"(built in [0-9.]+ ms| \(reused\)| \(the previous, turned\))");
    return std::regex_replace(t.report(), timing, "");
}

// Same content as a fresh build of the same scene: report text, env tables, and every product
// table's flat export (the arrays the GPU reads) word for word.
void expectSameAsFreshBuild(const scene::Scene& scene, const SceneSamplerTables& got) {
    SamplerTablesCache fresh;
    auto want = fresh.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(want.ok());
    EXPECT_EQ(got.samplerIndexOfMaterial, want->samplerIndexOfMaterial);
    const DirectionSamplerTables &a = *got.tables, &b = *want->tables;
    EXPECT_EQ(reportWithoutTimings(a), reportWithoutTimings(b));
    EXPECT_EQ(a.environment().level(), b.environment().level());
    EXPECT_EQ(a.environment().bytes(), b.environment().bytes());
    const int side = 1 << a.environment().level();
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            ASSERT_EQ(a.environment().cellAverage(a.environment().level(), x, y),
                      b.environment().cellAverage(b.environment().level(), x, y));
    EXPECT_EQ(a.environment().effectiveSolidAngle(), b.environment().effectiveSolidAngle());
    EXPECT_TRUE(a.environment().exact().pdfTable() == b.environment().exact().pdfTable());
    EXPECT_TRUE(a.environment().exact().columnCdf() == b.environment().exact().columnCdf());
    EXPECT_TRUE(a.environment().exact().rowCdf() == b.environment().exact().rowCdf());
    ASSERT_EQ(a.materialCount(), b.materialCount());
    for (size_t i = 0; i < a.materialCount(); ++i) {
        ASSERT_TRUE(a.productTables(i) && b.productTables(i));
        const FlatProductTables fa = a.productTables(i)->flatten(),
                                fb = b.productTables(i)->flatten();
        EXPECT_EQ(fa.header, fb.header) << a.material(i).name;
        EXPECT_EQ(fa.nodeWords, fb.nodeWords) << a.material(i).name;
        EXPECT_EQ(fa.scaling, fb.scaling) << a.material(i).name;
    }
}

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

// Every table is env-local (the unrotated map's), so a rotation turns the env tables — a copy
// with the new yaw and radiance lookup — and keeps every product table; the result is a fresh
// build's in content and in the world-frame answers (frames, env pdf, env draws).
TEST(SamplerTablesCache, EnvRotationTurnsTheEnvTablesAndKeepsEveryProductTable) {
    scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto before = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(before.ok());
    scene.lighting.environment.rotationDeg = 45.0f;
    auto after = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(after.ok());
    expectCounts(cache.rebuilds(), {1, 2, 0, 2});
    EXPECT_EQ(cache.rebuilds().environmentRotations, 1);
    EXPECT_NE(&after->tables->environment(), &before->tables->environment());
    EXPECT_EQ(product(*after, kGgx), product(*before, kGgx));
    EXPECT_EQ(product(*after, kLambert), product(*before, kLambert));
    EXPECT_FALSE(after->tables->environmentReused());
    EXPECT_TRUE(after->tables->environmentRotated());
    expectSameAsFreshBuild(scene, *after);

    SamplerTablesCache freshCache;
    auto fresh = freshCache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(fresh.ok());
    const SamplerEnvironment& turned = after->tables->environment();
    const SamplerEnvironment& built = fresh->tables->environment();
    int compared = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const glm::dvec2 u((i + 0.5) / 64.0, (j + 0.5) / 64.0);
            const wavelet::DirectionSample a = turned.sampleLocal(u), b = built.sampleLocal(u);
            ASSERT_EQ(a.direction, b.direction);
            ASSERT_EQ(a.pdf, b.pdf);
            const glm::vec3 world(turned.toWorld(a.direction));
            ASSERT_EQ(world, glm::vec3(built.toWorld(b.direction)));
            ASSERT_EQ(turned.pdfWorld(world), built.pdfWorld(world));
            ASSERT_EQ(turned.toLocal(glm::dvec3(world)), built.toLocal(glm::dvec3(world)));
            ++compared;
        }
    EXPECT_EQ(compared, 64 * 64);
    // And it is not the unturned tables' answer (the yaw took effect).
    const glm::dvec3 local = turned.sampleLocal({0.3, 0.6}).direction;
    EXPECT_NE(glm::vec3(before->tables->environment().toWorld(local)),
              glm::vec3(turned.toWorld(local)));
}

// An intensity edit keeps every table (they are built at intensity 1: tablesEnvironment), and the
// kept tables are a fresh build's at the new intensity, bit for bit.
TEST(SamplerTablesCache, EnvIntensityKeepsEveryTableAndTheyAreAFreshBuilds) {
    scene::Scene scene = testScene();
    SamplerTablesCache cache;
    auto before = cache.update(scene, SamplerKind::Wavelet);
    ASSERT_TRUE(before.ok());
    for (const float intensity : {3.7f, 1e-3f, 5e4f}) {
        scene.lighting.environment.intensity = intensity;
        auto after = cache.update(scene, SamplerKind::Wavelet);
        ASSERT_TRUE(after.ok());
        EXPECT_EQ(after->tables, before->tables) << intensity;
        EXPECT_EQ(cache.rebuilds().environmentBuilds, 1);
        EXPECT_EQ(cache.rebuilds().materialBuilds, 2);
        expectSameAsFreshBuild(scene, *after);
    }
}

// Every field of scene::Environment is an input: each edit rebuilds the env; an equal copy of the
// image (another pointer, same texels) does not, and neither does a positive intensity (the
// tables are built at intensity 1: tablesEnvironment); intensity 0 turns the env black.
TEST(SamplerTablesCache, EveryEnvironmentFieldInvalidatesAndAnEqualImageCopyDoesNot) {
    struct Edit {
        const char* what;
        void (*apply)(scene::Environment&);
        bool rebuilds;
    };
    const Edit edits[] = {
        {"intensity", [](scene::Environment& e) { e.intensity = 2.0f; }, false},
        {"intensity 0", [](scene::Environment& e) { e.intensity = 0.0f; }, true},
        {"tint", [](scene::Environment& e) { e.tint = glm::vec3(1.0f, 0.5f, 0.25f); }, true},
        {"path", [](scene::Environment& e) { e.path = "other.exr"; }, true},
        {"one texel",
         [](scene::Environment& e) {
             auto copy = std::make_shared<util::ImageRGB>(*e.image);
             copy->at(3, 5) *= 2.0f;
             e.image = copy;
         },
         true},
        {"equal copy",
         [](scene::Environment& e) { e.image = std::make_shared<util::ImageRGB>(*e.image); },
         false},
    };
    for (const Edit& edit : edits) {
        scene::Scene scene = testScene();
        SamplerTablesCache cache;
        auto before = cache.update(scene, SamplerKind::Wavelet);
        ASSERT_TRUE(before.ok());
        edit.apply(scene.lighting.environment);
        auto after = cache.update(scene, SamplerKind::Wavelet);
        ASSERT_TRUE(after.ok());
        EXPECT_EQ(cache.rebuilds().environmentBuilds, edit.rebuilds ? 2 : 1) << edit.what;
        EXPECT_EQ(cache.rebuilds().materialBuilds, edit.rebuilds ? 4 : 2) << edit.what;
        EXPECT_EQ(&after->tables->environment() == &before->tables->environment(), !edit.rebuilds)
            << edit.what;
    }
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
