#include "scene/mesh_loader.h"
#include "scene/mesh_loader_test_support.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <filesystem>

namespace wavelit::scene {
namespace {

namespace fs = std::filesystem;

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

// fuzz_gltf finding: a 29-byte GLB stating a 4 GB JSON chunk made Assimp allocate 4 GB before
// failing. Chunks that do not fit in the file are refused before Assimp reads them.
TEST_F(MeshLoader, GlbChunksLargerThanTheFileAreRefusedBeforeAllocation) {
    const std::string finding("glTF\x02\0\0\0\0\x10\0\0\x10\0\0\xf7JSON{bufferVi", 29);
    auto m = loadMesh(write("huge_chunk.glb", finding));
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.error().message(), (dir / "huge_chunk.glb").string() +
                                       ": cannot read mesh: GLB header states 4096 bytes (the file has 29 bytes)");
    // The same chunk in a header that states the file's true length.
    auto chunk = loadMesh(write("chunk.glb", std::string("glTF\x02\0\0\0\x1c\0\0\0\x10\0\0\xf7JSON{\"asset\"", 28)));
    ASSERT_FALSE(chunk.ok());
    EXPECT_NE(chunk.error().reason.find("GLB chunk at byte 12 states 4143972368 bytes (the file has 28 bytes)"), std::string::npos)
        << chunk.error().message();
    // A header stating fewer bytes than its own header skipped the chunk checks (second finding).
    auto tiny = loadMesh(write("tiny_length.glb", std::string("glTF\x02\0\0\0\x01\0\0\0\0\0\0\x96JSON{\"asset\"", 28)));
    ASSERT_FALSE(tiny.ok());
    EXPECT_EQ(tiny.error().message(), (dir / "tiny_length.glb").string() +
                                          ": cannot read mesh: GLB header states 1 bytes (the file has 28 bytes)");
    auto seed = loadMesh(std::string(WAVELIT_TEST_DATA_DIR) + "/../fuzz/corpus/fuzz_gltf/triangle.glb");
    ASSERT_TRUE(seed.ok()) << seed.error().message();
    EXPECT_EQ(seed->triangleCount(), 1u);
}

// fuzz_ply findings: a face list with a stray "[" gave Assimp a face without vertices in a mesh
// stating polygons it did not have; its triangulation asserted and `validate` aborted (exit 134);
// similar faces crashed a later step (SIGBUS). Such raw meshes are refused before post-processing.
TEST_F(MeshLoader, MeshStatingPolygonsItDoesNotHaveIsAnError) {
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                               "-1 0 -1\n1 0 -1\n1 0 1\n-1 0 1\n";
    auto m = loadMesh(write("bracket.ply", header + "[ 0 3 2 1\n"));
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.error().message(), (dir / "bracket.ply").string() +
                                       ": cannot read mesh: mesh 0 face 0 has no vertices (malformed face list)");
    auto quad = loadMesh(write("quad.ply", header + "4 0 3 2 1\n"));
    ASSERT_TRUE(quad.ok()) << quad.error().message();
    EXPECT_EQ(quad->triangleCount(), 2u);
}

// fuzz_gltf finding: a primitive without POSITION drawn as a line loop made Assimp dereference a
// null accessor (SEGV). A primitive without POSITION has no geometry: the file is refused.
TEST_F(MeshLoader, GltfPrimitiveWithoutPositionIsRefused) {
    const fs::path seed = fs::path(WAVELIT_TEST_DATA_DIR) / "../fuzz/corpus/fuzz_gltf/triangle_embedded.gltf";
    std::ifstream in(seed, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(loadMesh(write("ok.gltf", text)).ok());
    text.replace(text.find("\"POSITION\""), 10, "\"POPITION\"");
    text.replace(text.find("\"mode\":4"), 8, "\"mode\":2");
    auto m = loadMesh(write("no_position.gltf", text));
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.error().message(), (dir / "no_position.gltf").string() +
                                       ": cannot read mesh: glTF mesh 0 primitive 0 has no POSITION attribute");
    // The finding itself: the same, with a byte that is not UTF-8 inside a string.
    const fs::path finding = fs::path(WAVELIT_TEST_DATA_DIR) / "../fuzz/corpus/fuzz_gltf/finding_segv_line_loop_without_position.gltf";
    const std::string path = (dir / "finding.gltf").string();
    fs::copy_file(finding, path);
    auto f = loadMesh(path);
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.error().message(), path + ": cannot read mesh: glTF mesh 0 primitive 0 has no POSITION attribute");
}

// fuzz_gltf finding: a .gltf that the glTF readers declined was offered to every Assimp importer;
// the OpenGEX parser took it (it holds the word "indexarray") and read past its buffer. Only the
// readers of the extension see a file now; an extension no reader has is refused.
TEST_F(MeshLoader, OnlyTheReadersOfTheExtensionSeeTheFile) {
    const fs::path finding = fs::path(WAVELIT_TEST_DATA_DIR) / "../fuzz/corpus/fuzz_gltf/finding_asan_opengex_fallback.gltf";
    std::ifstream in(finding, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_NE(bytes.find("indexarray"), std::string::npos);
    auto m = loadMesh(write("opengex_words.gltf", bytes));
    ASSERT_FALSE(m.ok());
    EXPECT_NE(m.error().message().find("opengex_words.gltf: cannot read mesh: "), std::string::npos) << m.error().message();
    // An extension no reader declares is refused before any reader sees the file.
    auto named = loadMesh(write("words.xyz", "Metric {float {1.0}}\n"));
    ASSERT_FALSE(named.ok());
    EXPECT_EQ(named.error().message(), (dir / "words.xyz").string() + ": cannot read mesh: no mesh reader for '.xyz' files");
    auto upper = loadMesh(write("TRI.OBJ", "v 0 0 0\nv 1 0 0\nv 0 0 -1\nf 1 2 3\n"));
    ASSERT_TRUE(upper.ok()) << upper.error().message();
}

} // namespace
} // namespace wavelit::scene
