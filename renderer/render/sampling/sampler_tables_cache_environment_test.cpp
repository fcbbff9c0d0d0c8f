// SamplerTablesCache's environment edits (sampler_tables_cache_test.cpp has the rest): a rotation
// turns the env tables, an intensity keeps every table, any other field rebuilds them; whatever is
// kept or turned is a fresh build's in content.
#include "render/sampling/sampler_tables_cache_test_support.h"

#include <gtest/gtest.h>

#include <memory>

namespace wavelit::render {
namespace {

using namespace sampler_tables_test;

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

} // namespace
} // namespace wavelit::render
