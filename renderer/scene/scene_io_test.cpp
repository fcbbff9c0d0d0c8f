#include "scene/scene_io.h"

#include "scene/change_set.h"
#include "scene/scene_compare.h"
#include "plugins/brdf.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace wavelit::scene {
namespace {

namespace fs = std::filesystem;

const fs::path kResources = WAVELIT_RESOURCE_DIR;

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeText(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

// A scratch folder inside resources' sibling layout is not needed: saved scenes reference meshes
// by relative path, so round trips save next to the originals' folder structure in a temp tree.
struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("wavelit_scene_io_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

std::vector<fs::path> bundled(const char* folder, const char* ext) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(kResources / folder))
        if (e.path().extension() == ext) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// A minimal valid scene text around one object and one material, with an inline constant env.
std::string sceneText(const std::string& objectExtra = "", const std::string& top = "\"version\": 1") {
    return R"({"format": "wavelit-scene", )" + top + R"(, "name": "t",
      "materials": [{"id": 1, "name": "m", "brdf": "lambert"}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 1)" + objectExtra + R"(}],
      "lighting": {"environment": {"intensity": 1}}})";
}

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 0 -1\nf 1 2 3\n";

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

// "lambert, ggx": the plugin registry's names, as the messages list them.
std::string knownBrdfs() {
    std::string all;
    for (const std::string& n : plugins::brdfNames()) all += (all.empty() ? "" : ", ") + n;
    return all;
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
    EXPECT_EQ(knownBrdfs(), "lambert, ggx");
}

// Every unknown key and BRDF of a file is listed, one per line, then the error that stopped the
// reading; problems in a referenced setup are reported from the scene, naming both files.
TEST(SceneIo, EveryProblemOfAFileIsListed) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    const fs::path path = tmp.path / "many.wlscene";
    writeText(path, R"({"format": "wavelit-scene", "version": 1, "nmae": "x",
      "camera": {"fovy": 30},
      "materials": [{"id": 1, "name": "a", "brdf": "phong", "baseColour": [1, 0, 0]}],
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
                                "  material 'a' (/materials/0/brdf): unknown BRDF 'phong'; known: " + knownBrdfs() + "\n"
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

// Issue 15: a hand-edited number no double holds (1e999) made the JSON parser throw out_of_range,
// which escaped the loader and aborted `validate` (exit 134). It is a load error naming the file,
// the literal and its line, for setups, inline lighting and any other number of a scene.
TEST(SceneIo, NumberOverflowIsALoadErrorNamingTheFileAndLine) {
    const std::string setup = (fs::path(WAVELIT_TEST_DATA_DIR) / "bad/number_overflow.wllight").string();
    util::Result<LightingSetup> l = LightingSetup{};
    ASSERT_NO_THROW(l = loadLightingSetup(setup));
    ASSERT_FALSE(l.ok());
    EXPECT_EQ(l.error().kind, util::ErrorKind::Format);
    EXPECT_EQ(l.error().message(), setup + ": invalid JSON: number overflow parsing '1e999' at line 14");

    TempDir tmp;
    for (const std::string& edit : {std::string(R"(, "translation": [0, -1e999, 0])"), std::string(R"(, "scale": [1E+400, 1, 1])")}) {
        const fs::path file = tmp.path / "overflow.wlscene";
        writeText(file, sceneText(edit));
        util::Result<Scene> s = Scene{};
        ASSERT_NO_THROW(s = loadScene(file.string()));
        ASSERT_FALSE(s.ok());
        EXPECT_NE(s.error().message().find(file.string() + ": invalid JSON: number overflow parsing"), std::string::npos)
            << s.error().message();
        EXPECT_NE(s.error().message().find("at line 3"), std::string::npos) << s.error().message();
    }
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

// Issue 15 (found by review while fuzzing): an "extras" nested 100000 levels deep overflowed the
// stack (nlohmann's dump recurses per level): `validate` died with a segfault. Documents nesting
// deeper than 256 levels are refused before parsing; brackets inside strings do not count.
TEST(SceneIo, DeeplyNestedJsonIsALoadErrorNotAStackOverflow) {
    TempDir tmp;
    const fs::path file = tmp.path / "deep.wllight";
    auto setup = [](const std::string& extras) {
        return "{\"format\": \"wavelit-lighting\", \"version\": 1,\n \"name\": \"x\", \"extras\": " + extras + "}";
    };
    writeText(file, setup("{\"a\": " + std::string(100000, '[') + std::string(100000, ']') + "}"));
    util::Result<LightingSetup> l = LightingSetup{};
    ASSERT_NO_THROW(l = loadLightingSetup(file.string()));
    ASSERT_FALSE(l.ok());
    EXPECT_EQ(l.error().message(), file.string() + ": invalid JSON: nested deeper than 256 levels at line 2");
    // 255 levels of extras under the root object (256 in all) load and round-trip.
    writeText(file, setup("{\"a\": \"[[[{{{\", \"b\": " + std::string(254, '[') + std::string(254, ']') + "}"));
    auto ok = loadLightingSetup(file.string());
    ASSERT_TRUE(ok.ok()) << ok.error().message();
    ASSERT_TRUE(saveLightingSetup(*ok, (tmp.path / "saved.wllight").string()).ok());
    auto again = loadLightingSetup((tmp.path / "saved.wllight").string());
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(again->extras, ok->extras);
}

// Integers no int holds are refused as such (18446744073709551615 used to be read as -1 and
// reported as "-1 is outside [0, 64]").
TEST(SceneIo, HugeUnsignedIntegersAreOutOfRange) {
    TempDir tmp;
    const fs::path file = tmp.path / "big.wlscene";
    std::string text = sceneText();
    text.replace(text.find("\"name\": \"t\","), 12, "\"name\": \"t\", \"render\": {\"bounces\": 18446744073709551615},");
    writeText(file, text);
    auto s = loadScene(file.string());
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message(), file.string() + ":/render/bounces: bounces: integer out of range");
}

} // namespace
} // namespace wavelit::scene
