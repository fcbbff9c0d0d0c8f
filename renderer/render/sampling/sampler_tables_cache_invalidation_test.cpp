// SamplerTablesCache keyed by a change set's invalidations (architecture.md §5.B "What an edit
// rebuilds"): what is rebuilt follows what the change set says changed, not a comparison of the
// environment's texels — a light edit hands back the same tables even when the scene's image is
// another copy of the same texels, an env intensity edit keeps them (they are built at intensity
// 1), and any other environment edit rebuilds the env tables and every material's product tables
// (a rotation turns them).
#include "render/sampling/sampler_tables_cache.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "render/testing/sampler_test_envs.h"
#include "scene/change_set.h"

#include <gtest/gtest.h>

#include <memory>

namespace wavelit::render {
namespace {

scene::Scene glossyScene() {
    scene::Material ggx;
    ggx.name = "glossy";
    ggx.brdf = "ggx";
    ggx.roughness = 0.35f;
    scene::Scene s = *makeFurnaceScene(ggx, glm::vec3(1.0f), 32, 16);
    s.lighting.environment = makeSunSkyEnvironment(64, glm::vec3(0.3f, 0.8f, 0.5f), 200.0);
    return s;
}

std::vector<scene::Invalidation> invalidationsOf(const scene::Scene& s, scene::EntityRef ref,
                                                 const std::string& property,
                                                 scene::PropertyValue value) {
    scene::ChangeSet changes;
    EXPECT_TRUE(changes.setProperty(s, ref, property, value).ok());
    return changes.invalidations();
}

TEST(SamplerTablesCache, ALightEditReusesEverythingWithoutLookingAtTexels) {
    scene::Scene s = glossyScene();
    SamplerTablesCache cache;
    auto first = cache.update(s, SamplerKind::Wavelet);
    ASSERT_TRUE(first.ok());
    // Another copy of the same texels (a pointer the reuse test would otherwise compare texel by
    // texel) and a change set that touches only the camera: nothing is built, same tables.
    s.lighting.environment.image = std::make_shared<util::ImageRGB>(*s.lighting.environment.image);
    const auto changed = invalidationsOf(s, {scene::EntityKind::Camera, scene::kInvalidId}, "fov", 50.0f);
    auto second = cache.update(s, SamplerKind::Wavelet, &changed);
    ASSERT_TRUE(second.ok());
    EXPECT_EQ(second->tables, first->tables);
    EXPECT_EQ(cache.rebuilds().environmentBuilds, 1);
    EXPECT_EQ(cache.rebuilds().materialBuilds, 1);
}

TEST(SamplerTablesCache, AnEnvironmentEditRebuildsEnvAndProductTables) {
    scene::Scene s = glossyScene();
    SamplerTablesCache cache;
    ASSERT_TRUE(cache.update(s, SamplerKind::Wavelet).ok());
    const scene::EntityRef env{scene::EntityKind::Environment, scene::kInvalidId};
    // A rotation turns the env tables (env-local: nothing is rebuilt) and keeps the product tables.
    const auto turned = invalidationsOf(s, env, "rotation", 30.0f);
    s.lighting.environment.rotationDeg = 30.0f;
    auto rotated = cache.update(s, SamplerKind::Wavelet, &turned);
    ASSERT_TRUE(rotated.ok());
    EXPECT_FALSE(rotated->tables->environmentReused());
    EXPECT_TRUE(rotated->tables->environmentRotated());
    EXPECT_EQ(cache.rebuilds().environmentBuilds, 1);
    EXPECT_EQ(cache.rebuilds().environmentRotations, 1);
    EXPECT_EQ(cache.rebuilds().materialBuilds, 1);
    // An intensity edit keeps both: the same tables.
    const auto brighter = invalidationsOf(s, env, "intensity", 2.0f);
    s.lighting.environment.intensity = 2.0f;
    auto kept = cache.update(s, SamplerKind::Wavelet, &brighter);
    ASSERT_TRUE(kept.ok());
    EXPECT_EQ(kept->tables, rotated->tables);
    EXPECT_EQ(cache.rebuilds().environmentBuilds, 1);
    EXPECT_EQ(cache.rebuilds().materialBuilds, 1);
    // A tint edit rebuilds both.
    const auto changed = invalidationsOf(s, env, "tint", glm::vec3(1.0f, 0.5f, 0.25f));
    s.lighting.environment.tint = glm::vec3(1.0f, 0.5f, 0.25f);
    auto after = cache.update(s, SamplerKind::Wavelet, &changed);
    ASSERT_TRUE(after.ok());
    EXPECT_FALSE(after->tables->environmentReused());
    EXPECT_FALSE(after->tables->environmentRotated());
    EXPECT_EQ(cache.rebuilds().environmentBuilds, 2);
    EXPECT_EQ(cache.rebuilds().materialBuilds, 2);
    // A material edit keeps the environment (no env invalidation) and rebuilds that material.
    const scene::EntityRef glossy{scene::EntityKind::Material, s.materials[0].id};
    const auto rough = invalidationsOf(s, glossy, "roughness", 0.5f);
    s.materials[0].roughness = 0.5f;
    auto third = cache.update(s, SamplerKind::Wavelet, &rough);
    ASSERT_TRUE(third.ok());
    EXPECT_TRUE(third->tables->environmentReused());
    EXPECT_EQ(cache.rebuilds().environmentBuilds, 2);
    EXPECT_EQ(cache.rebuilds().materialBuilds, 3);
}

} // namespace
} // namespace wavelit::render
