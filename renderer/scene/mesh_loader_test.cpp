#include "scene/mesh_loader.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <filesystem>
#include <fstream>

namespace wavelit::scene {
namespace {

namespace fs = std::filesystem;

struct MeshLoader : ::testing::Test {
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("wavelit_mesh_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    }
};

TEST_F(MeshLoader, LoadsBundledTorusWithUnitNormals) {
    auto m = loadMesh(std::string(WAVELIT_RESOURCE_DIR) + "/meshes/torus.obj");
    ASSERT_TRUE(m.ok()) << m.error().message();
    EXPECT_EQ(m->triangleCount(), 4608u);
    ASSERT_EQ(m->normals.size(), m->positions.size());
    for (const auto& n : m->normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    // Ring radius 1 m + tube 0.12 m (make_meshes.py).
    float maxX = 0.0f;
    for (const auto& p : m->positions) maxX = std::max(maxX, p.x);
    EXPECT_NEAR(maxX, 1.12f, 1e-5f);
}

TEST_F(MeshLoader, TriangulatesQuadsAndGeneratesNormals) {
    auto m = loadMesh(write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nf 1 2 3 4\n"));
    ASSERT_TRUE(m.ok()) << m.error().message();
    EXPECT_EQ(m->triangleCount(), 2u);
    for (const auto& n : m->normals) EXPECT_NEAR(n.y, 1.0f, 1e-6f);
}

TEST_F(MeshLoader, SkipsZeroAreaTrianglesWithAWarning) {
    std::vector<std::string> warnings;
    auto m = loadMesh(write("z.obj", "v 0 0 0\nv 1 0 0\nv 0 0 -1\nv 2 0 0\nf 1 2 3\nf 1 2 4\n"), &warnings);
    ASSERT_TRUE(m.ok()) << m.error().message();
    EXPECT_EQ(m->triangleCount(), 1u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("skipped 1 zero-area triangles of 2"), std::string::npos) << warnings[0];
}

TEST_F(MeshLoader, RejectsBrokenMeshesNamingFileAndProblem) {
    struct Case {
        const char* name;
        std::string text;
        const char* reason;
    } cases[] = {
        {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 0 -1\nf 1 2 3\n", "vertex 1 is NaN or infinite"},
        {"nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 0 -1\n", ""},
        {"flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "all 1 triangles have zero area"},
        {"garbage.obj", "this is not a mesh\n\x01\x02", ""},
    };
    for (const auto& c : cases) {
        auto m = loadMesh(write(c.name, c.text));
        ASSERT_FALSE(m.ok()) << c.name;
        EXPECT_NE(m.error().file.find(c.name), std::string::npos);
        EXPECT_NE(m.error().reason.find(c.reason), std::string::npos) << m.error().message();
    }
    EXPECT_EQ(loadMesh((dir / "missing.obj").string()).error().kind, util::ErrorKind::NotFound);
}

} // namespace
} // namespace wavelit::scene
