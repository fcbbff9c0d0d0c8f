#include "scene/change_set.h"

#include "scene/scene_compare.h"

#include <gtest/gtest.h>

namespace wavelit::scene {
namespace {

Object makeObject(EntityId id, const char* name, const char* mesh, EntityId material) {
    Object o;
    o.id = id;
    o.name = name;
    o.meshPath = mesh;
    o.materialId = material;
    return o;
}

// Two of everything so edits can move references between entities; no assets are loaded.
Scene makeScene() {
    Scene s;
    s.name = "edits";
    s.materials = {Material{.id = 1, .name = "gold", .brdf = "ggx", .roughness = 0.2f},
                   Material{.id = 2, .name = "ground", .brdf = "lambert"}};
    s.objects = {makeObject(3, "ring", "ring.obj", 1), makeObject(4, "floor", "floor.obj", 2)};
    s.lighting.environment.path = "env.exr";
    s.lighting.lights = {Light{.id = 5, .name = "key", .type = LightType::Spot}};
    return s;
}

// A valid value different from `current` for the property: the generic edit the test applies.
PropertyValue otherValue(const PropertyInfo& info, const PropertyValue& current) {
    auto nudge = [&](float v) {
        const float step = 0.25f;
        return double(v) + step <= info.max ? v + step : v - step;
    };
    switch (info.type) {
    case PropertyType::Bool: return !std::get<bool>(current);
    case PropertyType::Int: {
        const int v = std::get<int>(current);
        return v + 1 <= info.max ? v + 1 : v - 1;
    }
    case PropertyType::Float: return nudge(std::get<float>(current));
    case PropertyType::Vec2: {
        glm::vec2 v = std::get<glm::vec2>(current);
        return glm::vec2(nudge(v.x), v.y);
    }
    case PropertyType::Vec3:
    case PropertyType::Color: {
        glm::vec3 v = std::get<glm::vec3>(current);
        return glm::vec3(v.x, nudge(v.y), v.z);
    }
    case PropertyType::Enum:
        for (const auto& o : info.enumOptions)
            if (o != std::get<std::string>(current)) return o;
        return current;
    case PropertyType::String:
    case PropertyType::Path: return std::get<std::string>(current) + "_edited";
    case PropertyType::IdRef: return EntityId(std::get<EntityId>(current) == 1 ? 2 : 1);
    }
    return current;
}

// What each kind's edits must invalidate, stated independently of the registry (architecture.md §5).
Invalidation expectedInvalidation(EntityRef ref, const std::string& name) {
    if (name == "name") return {};
    switch (ref.kind) {
    case EntityKind::Camera: return name == "exposure" ? Invalidation{} : Invalidation{FactorKind::Camera, 0};
    case EntityKind::Material: return {FactorKind::MaterialBrdf, ref.id};
    case EntityKind::Object:
        return {name == "material" ? FactorKind::ObjectMaterial : FactorKind::ObjectGeometry, ref.id};
    case EntityKind::Environment: return {FactorKind::Environment, 0};
    case EntityKind::Light: return {FactorKind::Light, ref.id};
    case EntityKind::Render: return {};
    }
    return {};
}

EntityRef refFor(EntityKind kind) {
    switch (kind) {
    case EntityKind::Material: return {kind, 1};
    case EntityKind::Object: return {kind, 4};
    case EntityKind::Light: return {kind, 5};
    default: return {kind, kInvalidId};
    }
}

TEST(ChangeSet, EveryPropertyAppliesInvertsAndNamesItsFactor) {
    int tested = 0;
    for (EntityKind kind : kAllEntityKinds) {
        for (const PropertyInfo& info : properties(kind)) {
            SCOPED_TRACE(std::string(entityKindName(kind)) + "." + info.name);
            const Scene original = makeScene();
            Scene scene = original;
            const EntityRef ref = refFor(kind);
            const PropertyValue before = *getProperty(scene, ref, info.name);
            const PropertyValue after = otherValue(info, before);
            ASSERT_NE(before, after);
            ChangeSet change;
            ASSERT_TRUE(change.setProperty(scene, ref, info.name, after).ok());
            ASSERT_TRUE(change.apply(scene).ok());
            EXPECT_EQ(*getProperty(scene, ref, info.name), after);
            EXPECT_NE(firstDifference(scene, original), "");
            const Invalidation expected = expectedInvalidation(ref, info.name);
            if (expected == Invalidation{})
                EXPECT_TRUE(change.invalidations().empty());
            else
                EXPECT_EQ(change.invalidations(), std::vector<Invalidation>{expected});
            ASSERT_TRUE(change.inverted().apply(scene).ok());
            EXPECT_EQ(firstDifference(scene, original), "");
            ++tested;
        }
    }
    EXPECT_EQ(tested, 40); // every property in docs/file-formats.md's table (light `group`, `muted`, environment `maskDirection`, `maskRadius`: issue 21; material `anisotropy`, `brdfFile`: issue 16)
}

TEST(ChangeSet, CostFollowsTheRegistry) {
    const Scene scene = makeScene();
    ChangeSet display, restart, rebuild;
    ASSERT_TRUE(display.setProperty(scene, {EntityKind::Camera}, "exposure", 1.5f).ok());
    ASSERT_TRUE(restart.setProperty(scene, {EntityKind::Light, 5}, "intensity", 50.0f).ok());
    ASSERT_TRUE(rebuild.setProperty(scene, {EntityKind::Object, 3}, "translation", glm::vec3(1, 0, 0)).ok());
    EXPECT_EQ(display.changeKind(), ChangeKind::Display);
    EXPECT_EQ(restart.changeKind(), ChangeKind::Restart);
    EXPECT_EQ(rebuild.changeKind(), ChangeKind::Rebuild);
    display.merge(rebuild);
    EXPECT_EQ(display.changeKind(), ChangeKind::Rebuild);
}

TEST(ChangeSet, RejectsInvalidValuesAndUnknownNames) {
    Scene scene = makeScene();
    ChangeSet c;
    EXPECT_FALSE(c.setProperty(scene, {EntityKind::Material, 1}, "roughness", 1.5f).ok());
    EXPECT_FALSE(c.setProperty(scene, {EntityKind::Material, 1}, "roughness", std::string("x")).ok());
    EXPECT_FALSE(c.setProperty(scene, {EntityKind::Material, 1}, "roughnes", 0.5f).ok());
    EXPECT_FALSE(c.setProperty(scene, {EntityKind::Material, 9}, "roughness", 0.5f).ok());
    EXPECT_FALSE(c.setProperty(scene, {EntityKind::Light, 5}, "type", std::string("laser")).ok());
    EXPECT_FALSE(c.setProperty(scene, {EntityKind::Object, 3}, "mesh", std::string("/abs/x.obj")).ok());
    EXPECT_TRUE(c.empty());
}

TEST(ChangeSet, MergeKeepsNewestValueAndFirstOldValue) {
    const Scene original = makeScene();
    Scene scene = original;
    const EntityRef light{EntityKind::Light, 5};
    ChangeSet queue;
    for (float v : {10.0f, 20.0f, 30.0f}) {
        ChangeSet drag;
        ASSERT_TRUE(drag.setProperty(scene, light, "intensity", v).ok());
        ASSERT_TRUE(drag.apply(scene).ok());
        queue.merge(drag);
    }
    ASSERT_EQ(queue.edits().size(), 1u);
    const auto& edit = std::get<PropertyEdit>(queue.edits()[0]);
    EXPECT_EQ(edit.oldValue, PropertyValue(100.0f)); // Light's default intensity
    EXPECT_EQ(edit.newValue, PropertyValue(30.0f));
    Scene replay = original;
    ASSERT_TRUE(queue.apply(replay).ok());
    EXPECT_EQ(firstDifference(replay, scene), "");
    ASSERT_TRUE(queue.inverted().apply(replay).ok());
    EXPECT_EQ(firstDifference(replay, original), "");
}

TEST(ChangeSet, AddAndRemoveEntitiesInvertInPlace) {
    const Scene original = makeScene();
    Scene scene = original;
    ChangeSet change;
    change.addObject(scene, makeObject(kInvalidId, "cube", "cube.obj", 2));
    ASSERT_TRUE(change.removeEntity(scene, {EntityKind::Material, 1}).ok()); // still referenced: allowed mid-edit
    ASSERT_TRUE(change.removeEntity(scene, {EntityKind::Light, 5}).ok());
    ASSERT_TRUE(change.apply(scene).ok());
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[2].id, 6u); // nextId: one past the largest id in use
    EXPECT_EQ(scene.materials.size(), 1u);
    EXPECT_TRUE(scene.lighting.lights.empty());
    EXPECT_EQ(change.changeKind(), ChangeKind::Rebuild);
    EXPECT_EQ(change.invalidations(), (std::vector<Invalidation>{{FactorKind::Light, 5},
                                                                 {FactorKind::ObjectGeometry, 6},
                                                                 {FactorKind::MaterialBrdf, 1}}));
    ASSERT_TRUE(change.inverted().apply(scene).ok());
    EXPECT_EQ(firstDifference(scene, original), "");
}

TEST(ChangeSet, FailedApplyLeavesSceneUntouched) {
    const Scene original = makeScene();
    Scene scene = original;
    ChangeSet change;
    ASSERT_TRUE(change.setProperty(scene, {EntityKind::Camera}, "fov", 60.0f).ok());
    ASSERT_TRUE(change.removeEntity(scene, {EntityKind::Light, 5}).ok());
    ASSERT_TRUE(change.apply(scene).ok());
    // Applying again fails at the removal (light 5 is gone); the fov edit must not stick either.
    Scene copy = original;
    copy.lighting.lights.clear();
    const Scene before = copy;
    EXPECT_FALSE(change.apply(copy).ok());
    EXPECT_EQ(firstDifference(copy, before), "");
}

TEST(ChangeSet, PathEditDropsTheStaleAsset) {
    Scene scene = makeScene();
    scene.objects[0].mesh = std::make_shared<TriangleMesh>();
    ChangeSet change;
    ASSERT_TRUE(change.setProperty(scene, {EntityKind::Object, 3}, "mesh", std::string("other.obj")).ok());
    ASSERT_TRUE(change.apply(scene).ok());
    EXPECT_EQ(scene.objects[0].mesh, nullptr); // scene_io's loadAssets() reloads it
}

} // namespace
} // namespace wavelit::scene
