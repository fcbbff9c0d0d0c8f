// BRDF data files (issue 16): a material whose plugin reads one (`brdfFile`, plugins::brdfReadsFile)
// gets its table when the scene loads, relative to the scene file like a mesh; materials naming
// the same file share one table; an edited path loads the new file; a new folder rebases it.
#include "scene/scene_io.h"
#include "scene/scene_io_test_support.h"

#include "plugins/brdf_table.h"

#include <gtest/gtest.h>

namespace wavelit::scene {
namespace {

using namespace scene_io_test;

const fs::path kExample = kResources / "brdfs/glossy-copper-r05.binary";

std::string measuredScene(const std::string& file) {
    return R"({"format": "wavelit-scene", "version": 1, "name": "t",
      "materials": [{"id": 1, "name": "a", "brdf": "measured", "brdfFile": ")" + file + R"("},
                    {"id": 2, "name": "b", "brdf": "measured", "brdfFile": ")" + file + R"("},
                    {"id": 3, "name": "c", "brdf": "lambert"}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 1}],
      "lighting": {"environment": {"intensity": 1}}})";
}

TEST(SceneIoBrdfTable, LoadsRelativeToTheSceneSharedAndReloadedWhenThePathChanges) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    fs::create_directories(tmp.path / "brdfs");
    fs::copy_file(kExample, tmp.path / "brdfs/one.binary");
    fs::copy_file(kExample, tmp.path / "brdfs/two.binary");
    writeText(tmp.path / "s.wlscene", measuredScene("brdfs/one.binary"));
    auto s = loadScene((tmp.path / "s.wlscene").string());
    ASSERT_TRUE(s.ok()) << s.error().message();
    ASSERT_TRUE(s->materials[0].brdfTable);
    EXPECT_EQ(s->materials[0].brdfTable, s->materials[1].brdfTable); // one table for one file
    EXPECT_FALSE(s->materials[2].brdfTable);                         // lambert reads no file
    EXPECT_EQ(brdfParamsOf(s->materials[0]).table, s->materials[0].brdfTable);
    EXPECT_EQ(s->materials[0].brdfTable->thetaDiffBins, 64);

    const auto first = s->materials[0].brdfTable;
    s->materials[0].brdfFile = "brdfs/two.binary";
    ASSERT_TRUE(loadAssets(*s, (tmp.path / "s.wlscene").string()).ok());
    EXPECT_NE(s->materials[0].brdfTable, first);
    EXPECT_NE(s->materials[0].brdfTable->file.find("two.binary"), std::string::npos);
    EXPECT_EQ(s->materials[1].brdfTable, first); // untouched

    // Saved elsewhere, the paths follow (as mesh paths do).
    rebaseScenePaths(*s, (tmp.path / "s.wlscene").string(), (tmp.path / "sub/saved.wlscene").string());
    EXPECT_EQ(s->materials[0].brdfFile, "../brdfs/two.binary");
    EXPECT_EQ(s->objects[0].meshPath, "../mesh.obj");
}

TEST(SceneIoBrdfTable, ABrokenFileIsAnErrorNamingSceneMaterialAndFile) {
    TempDir tmp;
    writeText(tmp.path / "mesh.obj", kTriangleObj);
    writeText(tmp.path / "bad.binary", "not a table");
    writeText(tmp.path / "s.wlscene", measuredScene("bad.binary"));
    auto s = loadScene((tmp.path / "s.wlscene").string());
    ASSERT_FALSE(s.ok());
    const std::string m = s.error().message();
    EXPECT_NE(m.find("s.wlscene"), std::string::npos) << m;
    EXPECT_NE(m.find("/materials/0/brdfFile"), std::string::npos) << m;
    EXPECT_NE(m.find("bad.binary"), std::string::npos) << m;
    EXPECT_NE(m.find("not a MERL BRDF file: 11 bytes"), std::string::npos) << m;
}

} // namespace
} // namespace wavelit::scene
