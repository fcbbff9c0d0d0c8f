// The MeshLoader test fixture: a temporary folder per test and files written into it. Shared by
// mesh_loader_test.cpp and mesh_loader_ply_test.cpp (the PLY checks' fuzz findings).
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace wavelit::scene {

struct MeshLoader : ::testing::Test {
    std::filesystem::path dir;
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("wavelit_mesh_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    }
};

} // namespace wavelit::scene
