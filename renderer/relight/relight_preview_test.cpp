// architecture.md §8 "cached products against full recomputation": after every kind of edit the
// incremental preview equals a preview built from scratch on the edited scene (≤ 1e-6 relative;
// per point the same inputs go through the same code, so in practice bit for bit).
#include "relight/relight_preview.h"
#include "relight/relight_test_support.h"
#include "relight/sphere_level.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wavelit::relight {
namespace {

struct EditCase {
    const char* name;
    scene::EntityKind kind;
    scene::EntityId id;
    const char* property;
    scene::PropertyValue value;
    const char* expectedKind;
};

void PrintTo(const EditCase& e, std::ostream* os) { *os << e.name; }

void expectSameImage(const util::ImageRGB& a, const util::ImageRGB& b) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = a.pixels[i][c], y = b.pixels[i][c];
            ASSERT_LE(std::abs(x - y), 1e-6 * std::max(std::abs(y), 1e-6)) << "pixel " << i << " channel " << c;
        }
}

class RelightEditTest : public ::testing::TestWithParam<EditCase> {};

TEST_P(RelightEditTest, IncrementalEqualsFromScratch) {
    const EditCase& e = GetParam();
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    const util::ImageRGB before = (*preview)->image();
    scene::ChangeSet changes;
    ASSERT_TRUE(changes.setProperty(scene, {e.kind, e.id}, e.property, e.value));
    ASSERT_TRUE(changes.apply(scene));
    const EditSummary summary = (*preview)->applyChanges(scene, changes);
    EXPECT_EQ(summary.kind, e.expectedKind);
    EXPECT_FALSE(summary.factorsRebuilt.empty());
    auto scratch = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(scratch);
    const util::ImageRGB after = (*preview)->image();
    expectSameImage(after, (*scratch)->image());
    // The edit did something visible (a test of nothing would pass too).
    double change = 0.0;
    for (size_t i = 0; i < after.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) change += std::abs(after.pixels[i][c] - before.pixels[i][c]);
    EXPECT_GT(change, 0.0);
}

using K = scene::EntityKind;
INSTANTIATE_TEST_SUITE_P(
    EveryEditKind, RelightEditTest,
    ::testing::Values(
        EditCase{"EnvRotation", K::Environment, 0, "rotation", 75.0f, "environment"},
        EditCase{"EnvIntensity", K::Environment, 0, "intensity", 2.5f, "environment"},
        EditCase{"EnvTint", K::Environment, 0, "tint", glm::vec3(1.0f, 0.5f, 0.2f), "environment"},
        EditCase{"PointMove", K::Light, 6, "position", glm::vec3(-1.0f, 1.5f, 1.5f), "light"},
        EditCase{"PointIntensity", K::Light, 6, "intensity", 120.0f, "light"},
        EditCase{"RectMove", K::Light, 7, "position", glm::vec3(-0.5f, 1.5f, 0.5f), "light"},
        EditCase{"SphereRadius", K::Light, 8, "radius", 0.2f, "light"},
        EditCase{"SunDirection", K::Light, 9, "direction", glm::vec3(0.4f, -1.0f, 0.1f), "light"},
        EditCase{"MaterialColor", K::Material, 1, "baseColor", glm::vec3(0.2f, 0.7f, 0.3f), "material"},
        EditCase{"MaterialRoughness", K::Material, 2, "roughness", 0.1f, "material"},
        EditCase{"ObjectMove", K::Object, 4, "translation", glm::vec3(0.6f, 0.5f, 0.3f), "object"},
        EditCase{"ObjectRotate", K::Object, 4, "rotation", glm::vec3(0.0f, 30.0f, 0.0f), "object"},
        EditCase{"ObjectMaterial", K::Object, 4, "material", scene::EntityId(1), "object"},
        EditCase{"Camera", K::Camera, 0, "position", glm::vec3(1.0f, 2.0f, 5.0f), "camera"}),
    [](const ::testing::TestParamInfo<EditCase>& info) { return std::string(info.param.name); });

TEST(RelightPreview, ASequenceOfEditsStaysEqualToFromScratch) {
    scene::Scene scene = testing::makeRelightScene();
    auto preview = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(preview);
    const std::vector<std::tuple<scene::EntityRef, const char*, scene::PropertyValue>> edits = {
        {{K::Object, 4}, "translation", glm::vec3(-0.8f, 0.5f, 0.0f)},
        {{K::Light, 6}, "intensity", 10.0f},
        {{K::Environment, 0}, "rotation", 200.0f},
        {{K::Material, 2}, "baseColor", glm::vec3(0.3f)},
        {{K::Object, 4}, "translation", glm::vec3(0.8f, 0.5f, -0.5f)}};
    for (const auto& [ref, property, value] : edits) {
        scene::ChangeSet changes;
        ASSERT_TRUE(changes.setProperty(scene, ref, property, value));
        ASSERT_TRUE(changes.apply(scene));
        (*preview)->applyChanges(scene, changes);
    }
    auto scratch = RelightPreview::create(scene, testing::smallSettings());
    ASSERT_TRUE(scratch);
    expectSameImage((*preview)->image(), (*scratch)->image());
}

TEST(RelightSphereLevel, FinerGridOnlyForALobeNarrowerThanHalfATexel) {
    scene::Scene scene = testing::makeRelightScene(); // GGX r = 0.3 on the box
    EXPECT_EQ(chooseSphereLevel(scene).level, 5) << chooseSphereLevel(scene).reason;
    scene.materials[1].roughness = 0.1f;
    EXPECT_EQ(chooseSphereLevel(scene).level, 6);
    EXPECT_NE(chooseSphereLevel(scene).reason.find("shiny"), std::string::npos);
    scene.objects[1].materialId = 1; scene.objects[2].materialId = 1; // the glossy material unused
    EXPECT_EQ(chooseSphereLevel(scene).level, 5);
}

TEST(RelightPreview, RefusesBadSettings) {
    RelightSettings s = testing::smallSettings();
    s.level = 9;
    EXPECT_FALSE(RelightPreview::create(testing::makeRelightScene(), s));
    s = testing::smallSettings();
    s.keep = 0;
    EXPECT_FALSE(RelightPreview::create(testing::makeRelightScene(), s));
}

} // namespace
} // namespace wavelit::relight
