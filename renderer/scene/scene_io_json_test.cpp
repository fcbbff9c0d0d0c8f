// JSON text no model value can hold is a load error naming the file and line, never a crash:
// numbers no double or int holds, nesting that would overflow the stack.
#include "scene/scene_io.h"
#include "scene/scene_io_test_support.h"

#include <gtest/gtest.h>

namespace wavelit::scene {
namespace {

using namespace scene_io_test;

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
