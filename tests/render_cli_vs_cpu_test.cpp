// End to end: `wavelit-cli render --device vulkan` on the bundled default scene writes an EXR
// that equals, pixel by pixel up to float rounding, what the CPU reference tracer computes in
// process with the same options (same estimator and random streams, docs/estimator.md).
// The scene keeps its analytic lights (the studio setup's rect softbox): both tracers sample
// them with the same next-event estimation, MIS and random draws (docs/estimator.md).
#include "render/session/render_session.h"
#include "scene/image_io.h"
#include "scene/scene_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace wavelit {
namespace {

namespace fs = std::filesystem;

TEST(RenderCli, VulkanExrMatchesCpuReference) {
    const fs::path resources(WAVELIT_RESOURCE_DIR);
    if (!fs::exists(resources / "scenes/ring_on_ground.wlscene"))
        GTEST_SKIP() << "default scene not present";
    fs::path dir = fs::temp_directory_path() / "wavelit_render_cli_vs_cpu";
    fs::remove_all(dir);
    fs::create_directories(dir / "envmaps");
    for (const char* sub : {"scenes", "meshes", "lighting"})
        fs::copy(resources / sub, dir / sub, fs::copy_options::recursive);
    fs::copy(resources / "envmaps/studio.exr", dir / "envmaps/studio.exr");
    // The lighting must still carry analytic lights, or this test no longer covers them.
    const fs::path lighting = dir / "lighting/studio_soft.wllight";
    nlohmann::json setup = nlohmann::json::parse(std::ifstream(lighting));
    ASSERT_FALSE(setup.value("lights", nlohmann::json::array()).empty());
    const std::string scenePath = (dir / "scenes/ring_on_ground.wlscene").string();
    const fs::path out = dir / "gpu.exr";
    const int size = 32, spp = 3, seed = 9, bounces = 3;
    std::string command = std::string("WAVELIT_VK_VALIDATION=1 '") + WAVELIT_CLI_PATH +
                          "' render '" + scenePath + "' -o '" + out.string() +
                          "' --device vulkan --width " + std::to_string(size) + " --height " +
                          std::to_string(size) + " --spp " + std::to_string(spp) + " --seed " +
                          std::to_string(seed) + " --bounces " + std::to_string(bounces) +
                          " --sampler mis --report '" + (dir / "report.json").string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    auto gpu = scene::loadImage(out.string(), {false});
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();

    auto scene = scene::loadScene(scenePath);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    render::RenderOptions options;
    options.width = options.height = size;
    options.seed = seed;
    options.bounces = bounces;
    options.device = render::DeviceChoice::Cpu;
    // `mis`: a sampler whose GPU form is a twin of the CPU's (the same numbers, the same paths).
    options.sampler = render::SamplerKind::Mis;
    auto session = render::RenderSession::create(*scene, options);
    ASSERT_TRUE(session.ok()) << session.error().message();
    for (int i = 0; i < spp; ++i)
        ASSERT_TRUE((*session)->renderPass().ok());
    auto cpu = (*session)->image();
    ASSERT_TRUE(cpu.ok());

    const util::ImageRGB& g = gpu->image;
    ASSERT_EQ(g.width, size);
    ASSERT_EQ(g.height, size);
    // LLVM and the C++ compiler round differently; where rounding flips a branch (roulette,
    // a grazing test) a path diverges, which a few pixels may show (2% of them on lavapipe at
    // 3 spp: the glossy ring's fireflies make a diverged pixel differ a lot).
    constexpr float kRelativeTolerance = 1e-3f;
    int differing = 0;
    double gpuSum = 0.0, cpuSum = 0.0;
    for (size_t i = 0; i < g.pixels.size(); ++i) {
        glm::vec3 a = g.pixels[i], b = cpu->pixels[i];
        ASSERT_TRUE(std::isfinite(a.r) && std::isfinite(a.g) && std::isfinite(a.b));
        gpuSum += util::luminance(a);
        cpuSum += util::luminance(b);
        float scale = std::max(1e-3f, util::luminance(b));
        glm::vec3 d = glm::abs(a - b);
        if (std::max(d.r, std::max(d.g, d.b)) > kRelativeTolerance * scale + 1e-5f)
            ++differing;
    }
    std::printf("cli vulkan vs in-process cpu: mean %.5f vs %.5f, %d of %zu pixels differ\n",
                gpuSum / g.pixels.size(), cpuSum / g.pixels.size(), differing, g.pixels.size());
    // Same random streams: all but the diverged pixels agree to kRelativeTolerance. The image sums
    // are not compared: at 3 spp one diverged firefly on the ring moves the mean by several
    // percent (seen: 7% from 9 of 1024 pixels); mean agreement in expectation is what
    // gpu_path_tracer_test's closed-form and CPU-vs-GPU statistical tests check.
    constexpr double kMaxDivergedFraction = 0.02;
    EXPECT_GT(gpuSum, 0.0);
    EXPECT_LE(differing, int(kMaxDivergedFraction * double(g.pixels.size())));
    fs::remove_all(dir);
}

} // namespace
} // namespace wavelit
