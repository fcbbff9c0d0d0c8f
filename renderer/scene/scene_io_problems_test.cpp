// What a file that does not mean what it says reports: versions (newer refused, older migrated),
// bad values with their JSON path, duplicates, unknown keys and BRDFs listed together, keys the
// light's type does not use.
#include "scene/scene_io.h"
#include "scene/scene_io_test_support.h"

#include "scene/scene_compare.h"
#include "plugins/brdf.h"

#include <gtest/gtest.h>

namespace wavelit::scene {
namespace {

using namespace scene_io_test;

// "lambert, ggx, glossy, phong, blinn, ward, measured": the plugin registry's names, as the messages list them.
std::string knownBrdfs() {
    std::string all;
    for (const std::string& n : plugins::brdfNames()) all += (all.empty() ? "" : ", ") + n;
    return all;
}

TEST(SceneIo, NewerVersionIsAClearError) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "new.wlscene", sceneText("", "\"version\": 7"));
    auto s = loadScene((tmp.path / "new.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().kind, util::ErrorKind::Unsupported);
    EXPECT_EQ(s.error().where, "/version");
    EXPECT_NE(s.error().reason.find("version 7 is newer"), std::string::npos) << s.error().message();
}

TEST(SceneIo, VersionZeroIsMigrated) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "old.wlscene", R"({"format": "wavelit-scene", "version": 0,
      "materials": [{"id": 5, "name": "gold", "brdf": "ggx"}],
      "objects": [{"id": 1, "mesh": "mesh.obj", "material": "gold"}],
      "lighting": {"environment": {"exposure": 2}}})");
    auto s = loadScene((tmp.path / "old.wlscene").string());
    ASSERT_TRUE(s.ok()) << s.error().message();
    EXPECT_EQ(s->objects[0].materialId, 5u);
    EXPECT_FLOAT_EQ(s->lighting.environment.intensity, 4.0f); // 2^2 EV
}

TEST(SceneIo, VersionZeroLightingIsMigratedAndBadNamesAreReported) {
    TempDir tmp;
    writeText(tmp.path / "old.wllight", R"({"format": "wavelit-lighting", "version": 0,
      "environment": {"exposure": -1}})");
    auto l = loadLightingSetup((tmp.path / "old.wllight").string());
    ASSERT_TRUE(l.ok()) << l.error().message();
    EXPECT_FLOAT_EQ(l->environment.intensity, 0.5f);
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "old.wlscene", R"({"format": "wavelit-scene", "version": 0,
      "objects": [{"id": 1, "mesh": "mesh.obj", "material": "silver"}]})");
    auto s = loadScene((tmp.path / "old.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().where, "/objects/0/material");
    EXPECT_EQ(s.error().reason, "material 'silver' not found");
}

TEST(SceneIo, ErrorsCarryTheJsonPath) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    struct Case {
        std::string text, where, fragment;
    } cases[] = {
        {sceneText(", \"translation\": \"up\""), "/objects/0/translation", "expected an array of 3 numbers"},
        {sceneText(", \"scale\": [1, 1]"), "/objects/0/scale", "got an array of 2"},
        {sceneText(", \"material\": 9"), "/objects/0/material", "material 9, which does not exist"},
        {sceneText(", \"mesh\": \"/etc/passwd\""), "/objects/0/mesh", "absolute path"},
        {sceneText(", \"rotation\": [0, 720, 0]"), "/objects/0/rotation", "outside"},
        {R"({"format": "wavelit-scene", "version": 1, "objects": [{"id": 1, "mesh": "mesh.obj"}]})",
         "/objects/0", "missing required key 'material'"},
        {R"({"format": "wavelit-lighting", "version": 1})", "/format", "expected \"wavelit-scene\""},
    };
    for (const auto& c : cases) {
        writeText(tmp.path / "bad.wlscene", c.text);
        auto s = loadScene((tmp.path / "bad.wlscene").string());
        ASSERT_FALSE(s.ok()) << c.text;
        EXPECT_EQ(s.error().where, c.where) << s.error().message();
        EXPECT_NE(s.error().message().find(c.fragment), std::string::npos) << s.error().message();
        EXPECT_NE(s.error().file.find("bad.wlscene"), std::string::npos);
    }
}

TEST(SceneIo, DuplicateIdsAndNamesAreRejected) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "dup.wlscene", R"({"format": "wavelit-scene", "version": 1,
      "materials": [{"id": 1, "name": "a", "brdf": "lambert"}, {"id": 1, "name": "b", "brdf": "lambert"}]})");
    auto s = loadScene((tmp.path / "dup.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().where, "/materials/1/id");
    writeText(tmp.path / "dup.wlscene", R"({"format": "wavelit-scene", "version": 1,
      "materials": [{"id": 1, "name": "a", "brdf": "lambert"}, {"id": 2, "name": "a", "brdf": "lambert"}]})");
    s = loadScene((tmp.path / "dup.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().reason.find("duplicate material name 'a'"), std::string::npos) << s.error().message();
}

TEST(SceneIo, UnknownKeyFailsTheLoadWithASuggestion) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "typo.wlscene", R"({"format": "wavelit-scene", "version": 1,
      "materials": [{"id": 1, "name": "m", "brdf": "ggx", "roughnes": 0.3}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 1}]})");
    LoadReport report;
    auto s = loadScene((tmp.path / "typo.wlscene").string(), &report);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message(), (tmp.path / "typo.wlscene").string() +
                                       ": unknown key 'roughnes' in /materials/0 (did you mean 'roughness'?)");
    EXPECT_TRUE(report.warnings.empty());
    // Far from every known key: no suggestion.
    writeText(tmp.path / "far.wlscene", R"({"format": "wavelit-scene", "version": 1, "shininess": 3})");
    s = loadScene((tmp.path / "far.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().reason, "unknown key 'shininess' in /");
}

TEST(SceneIo, UnknownBrdfNamesTheMaterialAndTheKnownOnes) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "phong.wlscene", R"({"format": "wavelit-scene", "version": 1,
      "materials": [{"id": 1, "name": "m", "brdf": "lambert"}, {"id": 2, "name": "ground", "brdf": "no_such_brdf"}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 2}]})");
    auto s = loadScene((tmp.path / "phong.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().reason,
              "material 'ground' (/materials/1/brdf): unknown BRDF 'no_such_brdf'; known: " + knownBrdfs());
    EXPECT_EQ(knownBrdfs(), "lambert, ggx, glossy, phong, blinn, ward, measured");
}

// Every unknown key and BRDF of a file is listed, one per line, then the error that stopped the
// reading; problems in a referenced setup are reported from the scene, naming both files.
TEST(SceneIo, EveryProblemOfAFileIsListed) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    const fs::path path = tmp.path / "many.wlscene";
    writeText(path, R"({"format": "wavelit-scene", "version": 1, "nmae": "x",
      "camera": {"fovy": 30},
      "materials": [{"id": 1, "name": "a", "brdf": "toon", "baseColour": [1, 0, 0]}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 1}],
      "lighting": {"environment": {"intensity": 1},
                   "lights": [{"id": 1, "type": "point", "intensty": 5, "color": "red"}]}})");
    auto s = loadScene(path.string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().file, path.string());
    EXPECT_EQ(s.error().reason, "6 problems:\n"
                                "  unknown key 'nmae' in / (did you mean 'name'?)\n"
                                "  unknown key 'fovy' in /camera (did you mean 'fov'?)\n"
                                "  unknown key 'baseColour' in /materials/0 (did you mean 'baseColor'?)\n"
                                "  material 'a' (/materials/0/brdf): unknown BRDF 'toon'; known: " + knownBrdfs() + "\n"
                                "  unknown key 'intensty' in /lighting/lights/0 (did you mean 'intensity'?)\n"
                                "  /lighting/lights/0/color: color: expected an array of 3 numbers, got a string");

    writeText(tmp.path / "l.wllight", R"({"format": "wavelit-lighting", "version": 1, "enviroment": {},
      "lights": [{"id": 1, "type": "point", "radius2": 1}]})");
    auto l = loadLightingSetup((tmp.path / "l.wllight").string());
    ASSERT_FALSE(l.ok());
    EXPECT_EQ(l.error().reason, "2 problems:\n"
                                "  unknown key 'enviroment' in / (did you mean 'environment'?)\n"
                                "  unknown key 'radius2' in /lights/0 (did you mean 'radius'?)");
    writeText(tmp.path / "ref.wlscene", R"({"format": "wavelit-scene", "version": 1, "lighting": "l.wllight"})");
    s = loadScene((tmp.path / "ref.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().where, "/lighting");
    EXPECT_EQ(s.error().reason, l.error().message());
}

// fuzz_lighting finding: a key the light's type does not use (coneInner on a rect light) was read into
// the model and dropped by the next save, so save + load changed the setup. It fails the load, listed
// like an unknown key; the same keys on a spot light load and round-trip.
TEST(SceneIo, KeyThatDoesNotApplyToTheLightTypeIsAProblem) {
    TempDir tmp;
    const fs::path file = tmp.path / "l.wllight";
    auto setup = [](const std::string& type) {
        return R"({"format": "wavelit-lighting", "version": 1, "name": "l", "lights": [
          {"id": 1, "name": "a", "type": ")" + type + R"(", "coneInner": 15, "radius": 0.5}]})";
    };
    writeText(file, setup("rect"));
    auto rect = loadLightingSetup(file.string());
    ASSERT_FALSE(rect.ok());
    EXPECT_EQ(rect.error().message(), file.string() + ": 2 problems:\n"
              "  key 'radius' in /lights/0 does not apply to a rect light\n"
              "  key 'coneInner' in /lights/0 does not apply to a rect light");
    writeText(file, setup("spot"));
    auto spot = loadLightingSetup(file.string());
    ASSERT_FALSE(spot.ok());
    EXPECT_EQ(spot.error().message(), file.string() + ": key 'radius' in /lights/0 does not apply to a spot light");

    writeText(file, R"({"format": "wavelit-lighting", "version": 1, "name": "l", "lights": [
      {"id": 1, "name": "a", "type": "spot", "coneInner": 15}]})");
    auto ok = loadLightingSetup(file.string());
    ASSERT_TRUE(ok.ok()) << ok.error().message();
    ASSERT_TRUE(saveLightingSetup(*ok, (tmp.path / "saved.wllight").string()).ok());
    auto again = loadLightingSetup((tmp.path / "saved.wllight").string());
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(firstDifference(*ok, *again), "");
    EXPECT_FLOAT_EQ(again->lights[0].coneInnerDeg, 15.0f);
}

} // namespace
} // namespace wavelit::scene
