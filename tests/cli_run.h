// Shared by the integration tests that run wavelit-cli (partial_merge_test, mpi_render_test): a
// private copy of the bundled default scene in a temp folder, the CLI run there with Vulkan
// validation on (a validation message fails the test), and the images it wrote.
#pragma once

#include "scene/image_io.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace wavelit::cli_run {

namespace fs = std::filesystem;

class TempScene {
public:
    explicit TempScene(const std::string& name)
        : m_dir(fs::temp_directory_path() /
                ("wavelit_" + name + "_" + std::to_string(::getpid()))) {
        const fs::path resources(WAVELIT_RESOURCE_DIR);
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / "envmaps");
        for (const char* sub : {"scenes", "meshes", "lighting"})
            fs::copy(resources / sub, m_dir / sub, fs::copy_options::recursive);
        fs::copy(resources / "envmaps/studio.exr", m_dir / "envmaps/studio.exr");
    }
    ~TempScene() { fs::remove_all(m_dir); }

    std::string path() const { return "scenes/ring_on_ground.wlscene"; }
    std::string file(const std::string& name) const { return (m_dir / name).string(); }

    // Runs `prefix wavelit-cli args` in the folder; returns the exit code. Output goes to the
    // test log.
    int cli(const std::string& args, const std::string& prefix = "") const {
        const std::string log = file("cli.log");
        const std::string command = "cd '" + m_dir.string() + "' && WAVELIT_VK_VALIDATION=1 " +
                                    prefix + " '" + WAVELIT_CLI_PATH + "' " + args + " >'" + log +
                                    "' 2>&1";
        const int status = std::system(command.c_str());
        std::stringstream out;
        out << std::ifstream(log).rdbuf();
        std::printf("$ %s\n%s", command.c_str(), out.str().c_str());
        EXPECT_EQ(out.str().find("validation messages"), std::string::npos) << out.str();
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    }

    util::ImageRGB image(const std::string& name) const {
        auto loaded = scene::loadImage(file(name), {false});
        EXPECT_TRUE(loaded.ok()) << loaded.error().message();
        return loaded.ok() ? loaded->image : util::ImageRGB{};
    }

private:
    fs::path m_dir;
};

} // namespace wavelit::cli_run
