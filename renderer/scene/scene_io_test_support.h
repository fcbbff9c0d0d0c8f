// Scratch files for the scene_io tests (scene_io_*test.cpp): a temp folder per test, a minimal
// valid scene text and its one-triangle mesh, the bundled files, byte-exact reads.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace wavelit::scene::scene_io_test {

namespace fs = std::filesystem;

inline const fs::path kResources = WAVELIT_RESOURCE_DIR;

inline std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeText(const fs::path& p, const std::string& text) {
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

inline std::vector<fs::path> bundled(const char* folder, const char* ext) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(kResources / folder))
        if (e.path().extension() == ext) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// A minimal valid scene text around one object and one material, with an inline constant env.
inline std::string sceneText(const std::string& objectExtra = "", const std::string& top = "\"version\": 1") {
    return R"({"format": "wavelit-scene", )" + top + R"(, "name": "t",
      "materials": [{"id": 1, "name": "m", "brdf": "lambert"}],
      "objects": [{"id": 1, "name": "o", "mesh": "mesh.obj", "material": 1)" + objectExtra + R"(}],
      "lighting": {"environment": {"intensity": 1}}})";
}

inline const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 0 -1\nf 1 2 3\n";

} // namespace wavelit::scene::scene_io_test
