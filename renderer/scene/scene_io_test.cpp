// Scenes and lighting setups through save and load: every bundled file round-trips, inline and
// referenced lighting (borrowed chains, cycles), "extras" kept, assets loaded and reloaded, setups
// attached and scenes rebased for "save as".
#include "scene/scene_io.h"
#include "scene/scene_io_test_support.h"

#include "scene/change_set.h"
#include "scene/scene_compare.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace wavelit::scene {
namespace {

using namespace scene_io_test;

TEST(SceneIo, BundledScenesLoadWithTheirMeshesAndLighting) {
    auto scenes = bundled("scenes", ".wlscene");
    ASSERT_GE(scenes.size(), 3u);
    for (const auto& path : scenes) {
        auto s = loadScene(path.string());
        ASSERT_TRUE(s.ok()) << s.error().message();
        for (const auto& o : s->objects) EXPECT_TRUE(o.mesh && o.mesh->triangleCount() > 0) << o.name;
        EXPECT_TRUE(s->lighting.environment.image) << path;
    }
}

TEST(SceneIo, RingOnGroundIsThePapersScene) {
    auto s = loadScene((kResources / "scenes/ring_on_ground.wlscene").string());
    ASSERT_TRUE(s.ok()) << s.error().message();
    ASSERT_EQ(s->objects.size(), 2u);
    const Material* ring = s->findMaterial(s->objects[0].materialId);
    ASSERT_NE(ring, nullptr);
    EXPECT_EQ(ring->brdf, "ggx");
    EXPECT_FLOAT_EQ(ring->roughness, 0.2f);
    EXPECT_EQ(s->findMaterial(s->objects[1].materialId)->brdf, "lambert");
    EXPECT_EQ(s->objects[0].mesh->triangleCount(), 96u * 24u * 2u); // make_meshes.py torus grid
    EXPECT_EQ(s->lightingPath, "../lighting/studio_soft.wllight");
    EXPECT_EQ(s->lighting.environment.path, "../envmaps/studio.exr");
    EXPECT_EQ(s->lighting.environment.image->width, 512); // bundled maps are downsampled to 512x256 (resources/LICENSES.md)
}

// Round trip for every bundled file: load -> save -> load gives the same model, and saving the
// reloaded model again gives the same bytes. Saved copies live in a temp tree mirroring
// resources/ so their relative paths still resolve.
TEST(SceneIo, EveryBundledFileRoundTrips) {
    TempDir tmp;
    for (const char* folder : {"meshes", "envmaps"})
        fs::create_directory_symlink(kResources / folder, tmp.path / folder);
    fs::create_directories(tmp.path / "scenes");
    fs::create_directories(tmp.path / "lighting");
    int files = 0;
    for (const auto& path : bundled("lighting", ".wllight")) {
        auto a = loadLightingSetup(path.string());
        ASSERT_TRUE(a.ok()) << a.error().message();
        const fs::path out = tmp.path / "lighting" / path.filename();
        ASSERT_TRUE(saveLightingSetup(*a, out.string()).ok());
        auto b = loadLightingSetup(out.string());
        ASSERT_TRUE(b.ok()) << b.error().message();
        EXPECT_EQ(firstDifference(*a, *b), "") << path;
        const std::string first = readBytes(out);
        ASSERT_TRUE(saveLightingSetup(*b, out.string()).ok());
        EXPECT_EQ(readBytes(out), first) << path;
        ++files;
    }
    for (const auto& path : bundled("scenes", ".wlscene")) {
        auto a = loadScene(path.string());
        ASSERT_TRUE(a.ok()) << a.error().message();
        const fs::path out = tmp.path / "scenes" / path.filename();
        ASSERT_TRUE(saveScene(*a, out.string()).ok());
        auto b = loadScene(out.string());
        ASSERT_TRUE(b.ok()) << b.error().message();
        EXPECT_EQ(firstDifference(*a, *b), "") << path;
        const std::string first = readBytes(out);
        ASSERT_TRUE(saveScene(*b, out.string()).ok());
        EXPECT_EQ(readBytes(out), first) << path;
        ++files;
    }
    EXPECT_EQ(files, 6);
}

TEST(SceneIo, InlineLightingRoundTripsInsideTheScene) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "a.wlscene", sceneText());
    auto a = loadScene((tmp.path / "a.wlscene").string());
    ASSERT_TRUE(a.ok()) << a.error().message();
    a->lighting.lights.push_back(Light{.id = 4, .name = "spot", .type = LightType::Spot, .intensity = 7.5f});
    ASSERT_TRUE(saveScene(*a, (tmp.path / "b.wlscene").string()).ok());
    auto b = loadScene((tmp.path / "b.wlscene").string());
    ASSERT_TRUE(b.ok()) << b.error().message();
    EXPECT_EQ(firstDifference(*a, *b), "");
    ASSERT_EQ(b->lighting.lights.size(), 1u);
    EXPECT_EQ(b->lighting.lights[0].type, LightType::Spot);
    EXPECT_FLOAT_EQ(b->lighting.lights[0].intensity, 7.5f);
}

// "extras" on the roots and on every entity is kept as it is and written back; it is never a problem.
TEST(SceneIo, ExtrasRoundTripUnchanged) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    const std::string text = R"({"format": "wavelit-scene", "version": 1, "name": "x",
      "extras": {"dcc": {"tool": "blender", "version": [4, 2]}, "note": "übersicht", "n": 1e-7, "big": 12345678901234},
      "camera": {"fov": 35, "extras": {"rig": "crane"}},
      "render": {"extras": {"farm": null}},
      "materials": [{"id": 1, "name": "m", "brdf": "ggx", "extras": {"substance": {"graph": "gold.sbsar", "seed": 7}}}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 1, "extras": {"tags": ["hero", true, 0.5]}}],
      "lighting": {"extras": {"look": "dusk"}, "environment": {"intensity": 2, "extras": {}},
                   "lights": [{"id": 1, "type": "point", "extras": {"gobo": "leaves.png", "z": -0.0}}]}})";
    writeText(tmp.path / "a.wlscene", text);
    LoadReport report;
    auto a = loadScene((tmp.path / "a.wlscene").string(), &report);
    ASSERT_TRUE(a.ok()) << a.error().message();
    EXPECT_TRUE(report.warnings.empty());
    EXPECT_EQ(a->materials[0].extras, R"({"substance":{"graph":"gold.sbsar","seed":7}})");
    EXPECT_EQ(a->lighting.environment.extras, "{}");
    ASSERT_TRUE(saveScene(*a, (tmp.path / "b.wlscene").string()).ok());
    auto b = loadScene((tmp.path / "b.wlscene").string());
    ASSERT_TRUE(b.ok()) << b.error().message();
    EXPECT_EQ(firstDifference(*a, *b), "");
    // Every "extras" object of the saved file equals the original's, value for value.
    const auto original = nlohmann::json::parse(text), saved = nlohmann::json::parse(readBytes(tmp.path / "b.wlscene"));
    for (const char* at : {"/extras", "/camera/extras", "/render/extras", "/materials/0/extras", "/objects/0/extras",
                           "/lighting/extras", "/lighting/environment/extras", "/lighting/lights/0/extras"}) {
        const nlohmann::json::json_pointer ptr(at);
        ASSERT_TRUE(saved.contains(ptr)) << at;
        EXPECT_EQ(saved.at(ptr), original.at(ptr)) << at;
    }
    // No extras, no key: files without them save as before.
    a->materials[0].extras.clear();
    ASSERT_TRUE(saveScene(*a, (tmp.path / "c.wlscene").string()).ok());
    EXPECT_FALSE(nlohmann::json::parse(readBytes(tmp.path / "c.wlscene"))["materials"][0].contains("extras"));

    // A *.wllight keeps its own.
    writeText(tmp.path / "l.wllight", R"({"format": "wavelit-lighting", "version": 1, "extras": {"by": "me"},
      "lights": [{"id": 3, "type": "sun", "extras": {"k": [1, 2]}}]})");
    auto l = loadLightingSetup((tmp.path / "l.wllight").string());
    ASSERT_TRUE(l.ok()) << l.error().message();
    ASSERT_TRUE(saveLightingSetup(*l, (tmp.path / "l2.wllight").string()).ok());
    const auto light = nlohmann::json::parse(readBytes(tmp.path / "l2.wllight"));
    EXPECT_EQ(light["extras"], nlohmann::json::parse(R"({"by": "me"})"));
    EXPECT_EQ(light["lights"][0]["extras"], nlohmann::json::parse(R"({"k": [1, 2]})"));

    // Extras must be an object.
    writeText(tmp.path / "bad.wlscene", R"({"format": "wavelit-scene", "version": 1, "camera": {"extras": 3}})");
    auto bad = loadScene((tmp.path / "bad.wlscene").string());
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().where, "/camera/extras");
    EXPECT_EQ(bad.error().reason, "extras: expected an object, got a number");
}

TEST(SceneIo, MissingMeshNamesSceneObjectAndMesh) {
    TempDir tmp;
    writeText(tmp.path / "m.wlscene", sceneText());
    auto s = loadScene((tmp.path / "m.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().kind, util::ErrorKind::NotFound);
    EXPECT_EQ(s.error().where, "/objects/0/mesh");
    EXPECT_NE(s.error().reason.find("mesh.obj: no such mesh file"), std::string::npos) << s.error().message();
}

// An edit of a path drops the asset (registry setter); loadAssets brings the new one in, resolving
// a referenced lighting setup's map against the *.wllight's folder.
TEST(SceneIo, LoadAssetsReloadsWhatAnEditInvalidated) {
    const std::string path = (kResources / "scenes/ring_on_ground.wlscene").string();
    auto s = loadScene(path);
    ASSERT_TRUE(s.ok()) << s.error().message();
    const auto oldImage = s->lighting.environment.image;
    const auto groundMesh = s->objects[1].mesh;
    ChangeSet edit;
    ASSERT_TRUE(edit.setProperty(*s, {EntityKind::Environment}, "map", std::string("../envmaps/city.exr")).ok());
    ASSERT_TRUE(edit.setProperty(*s, {EntityKind::Object, s->objects[0].id}, "mesh", std::string("../meshes/uv_sphere.obj")).ok());
    ASSERT_TRUE(edit.apply(*s).ok());
    EXPECT_EQ(s->lighting.environment.image, nullptr);
    ASSERT_TRUE(loadAssets(*s, path).ok());
    ASSERT_NE(s->lighting.environment.image, nullptr);
    EXPECT_NE(s->lighting.environment.image, oldImage);
    EXPECT_EQ(s->objects[0].mesh->triangleCount(), 3968u); // uv_sphere.obj
    EXPECT_EQ(s->objects[1].mesh, groundMesh);             // untouched assets are kept, not reloaded
}

TEST(SceneIo, LightingSetupsLoadOntoAnyScene) {
    TempDir tmp;
    const std::string from = (kResources / "scenes/glossy_sphere.wlscene").string();
    auto s = loadScene(from);
    ASSERT_TRUE(s.ok()) << s.error().message();
    ASSERT_TRUE(attachLightingSetup(*s, from, (kResources / "lighting/night_emissive.wllight").string()).ok());
    EXPECT_EQ(s->lightingPath, "../lighting/night_emissive.wllight");
    EXPECT_EQ(s->lighting.lights.size(), 3u);
    EXPECT_TRUE(s->lighting.environment.image);
    // "Save as" elsewhere: paths are rebased so the copy loads the same meshes and lighting.
    const std::string to = (tmp.path / "deeper/copy.wlscene").string();
    fs::create_directories(tmp.path / "deeper");
    rebaseScenePaths(*s, from, to);
    EXPECT_EQ(fs::weakly_canonical(tmp.path / "deeper" / s->objects[0].meshPath),
              fs::weakly_canonical(kResources / "meshes/uv_sphere.obj"));
    ASSERT_TRUE(saveScene(*s, to).ok());
    auto copy = loadScene(to);
    ASSERT_TRUE(copy.ok()) << copy.error().message();
    EXPECT_EQ(firstDifference(*s, *copy), "");
    EXPECT_EQ(copy->lighting.name, "night_emissive");
    EXPECT_EQ(copy->objects[0].mesh->triangleCount(), 3968u);
    EXPECT_FALSE(attachLightingSetup(*copy, to, (tmp.path / "none.wllight").string()).ok());
    EXPECT_EQ(copy->lighting.name, "night_emissive");
}

TEST(SceneIo, CyclicLightingReferencesAreFound) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "a.wlscene", R"({"format": "wavelit-scene", "version": 1, "lighting": "b.wlscene"})");
    writeText(tmp.path / "b.wlscene", R"({"format": "wavelit-scene", "version": 1, "lighting": "a.wlscene"})");
    auto s = loadScene((tmp.path / "a.wlscene").string());
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().reason.find("cyclic lighting reference: a.wlscene -> b.wlscene -> a.wlscene"),
              std::string::npos)
        << s.error().message();
}

TEST(SceneIo, BorrowedLightingKeepsItsEnvironmentPathValid) {
    TempDir tmp;
    // c.wlscene borrows from sub/b.wlscene, which references ../light/l.wllight.
    writeText(tmp.path / "light/l.wllight", R"({"format": "wavelit-lighting", "version": 1,
      "environment": {"map": "../env/e.exr"}})");
    writeText(tmp.path / "sub/b.wlscene", R"({"format": "wavelit-scene", "version": 1, "lighting": "../light/l.wllight"})");
    writeText(tmp.path / "c.wlscene", R"({"format": "wavelit-scene", "version": 1, "lighting": "sub/b.wlscene"})");
    fs::create_directories(tmp.path / "env");
    fs::copy_file(kResources / "envmaps/studio.exr", tmp.path / "env/e.exr");
    auto s = loadScene((tmp.path / "c.wlscene").string());
    ASSERT_TRUE(s.ok()) << s.error().message();
    EXPECT_EQ(s->lightingPath, "sub/b.wlscene");
    EXPECT_EQ(s->lighting.environment.path, "../env/e.exr"); // relative to sub/
    EXPECT_TRUE(s->lighting.environment.image);
}

} // namespace
} // namespace wavelit::scene
