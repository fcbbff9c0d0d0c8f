// Issue 17: `mpirun -n 2 wavelit-cli render ... --mpi` on localhost writes the image the
// single-process render of the same passes writes (the ranks split the passes, rank 0 sums them),
// within 1e-5 relative. Skipped when wavelit-cli was built without MPI (CMake found none); then
// `render --mpi` must say so.
#include "cli_run.h"

#include "scene/image_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wavelit {
namespace {

using cli_run::TempScene;

#ifdef WAVELIT_MPIEXEC
void expectRanksMatchOneProcess(const std::string& device) {
    TempScene scene("mpi_render_" + device);
    // 7 passes: rank 0 renders passes 0..3, rank 1 passes 4..6.
    const std::string flags =
        " --width 16 --height 12 --seed 6 --bounces 3 --sampler mis --spp 7 --device " + device;
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o one.exr" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o ranks.exr --mpi" + flags,
                        std::string(WAVELIT_MPIEXEC) + " --allow-run-as-root --oversubscribe -n 2"),
              0);
    const util::ImageRGB one = scene.image("one.exr"), ranks = scene.image("ranks.exr");
    ASSERT_EQ(ranks.pixels.size(), one.pixels.size());
    double worst = 0.0;
    for (size_t i = 0; i < one.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(ranks.pixels[i][c]) - one.pixels[i][c]) /
                                        std::max(std::abs(double(one.pixels[i][c])), 1e-6));
    std::printf("%s: 2 ranks vs 1 process, worst relative difference %.3g\n", device.c_str(),
                worst);
    EXPECT_LE(worst, 1e-5) << device;
    auto attributes = scene::readExrAttributes(scene.file("ranks.exr"));
    ASSERT_TRUE(attributes.ok()) << attributes.error().message();
    EXPECT_EQ(attributes->at("wavelit:passes"), "0:7");
    EXPECT_EQ(attributes->at("wavelit:tracer"), device);
}

TEST(MpiRender, TwoRanksOnCpuMatchOneProcess) {
    expectRanksMatchOneProcess("cpu");
}

TEST(MpiRender, TwoRanksOnVulkanMatchOneProcess) {
    expectRanksMatchOneProcess("vulkan");
}
#else
TEST(MpiRender, TwoRanksMatchOneProcess) {
    GTEST_SKIP() << "wavelit-cli was built without MPI (no MPI found by CMake)";
}

TEST(MpiRender, WithoutMpiTheFlagSaysSo) {
    TempScene scene("mpi_render_none");
    EXPECT_EQ(scene.cli("render " + scene.path() + " -o x.exr --mpi --spp 2"), 1);
    // cli() prints the output; the message names what is missing.
    std::ifstream log(scene.file("cli.log"));
    std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("built without MPI"), std::string::npos) << text;
}
#endif

} // namespace
} // namespace wavelit
