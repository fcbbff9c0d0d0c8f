// Issue 17 end to end: `wavelit-cli render --passes 0:3` and `--passes 3:5` merged with
// `wavelit-cli merge` equal `render --spp 8` within 1e-5 relative (float summation order), on the
// CPU reference tracer and on Vulkan; the merged file says which passes it holds and merges
// again. (Refusals and exit codes: tests/cli_merge_test.sh.)
#include "cli_run.h"

#include "scene/image_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wavelit {
namespace {

using cli_run::TempScene;

// Worst per-channel |a - b| / |b| (|b| floored at 1e-6: black pixels must stay black).
double worstRelative(const util::ImageRGB& a, const util::ImageRGB& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.pixels.size() != b.pixels.size()) return 1e30;
    double worst = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(a.pixels[i][c]) - b.pixels[i][c]) /
                                        std::max(std::abs(double(b.pixels[i][c])), 1e-6));
    return worst;
}

void expectMergeEqualsOneRender(const std::string& device) {
    TempScene scene("partial_merge_" + device);
    const std::string flags =
        " --width 16 --height 12 --seed 4 --bounces 3 --sampler mis --device " + device;
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o whole.exr --spp 8" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o a.exr --passes 0:3" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o b.exr --passes 3:5" + flags), 0);
    // Parts in any order.
    ASSERT_EQ(scene.cli("merge b.exr a.exr -o merged.exr"), 0);
    const util::ImageRGB whole = scene.image("whole.exr"), merged = scene.image("merged.exr");
    const double worst = worstRelative(merged, whole);
    std::printf("%s: merged 0:3 + 3:5 vs 8 spp, worst relative difference %.3g\n", device.c_str(),
                worst);
    EXPECT_LE(worst, 1e-5) << device;
    EXPECT_GT(worstRelative(scene.image("a.exr"), whole), 1e-3) << "the parts alone differ";

    auto attributes = scene::readExrAttributes(scene.file("merged.exr"));
    ASSERT_TRUE(attributes.ok()) << attributes.error().message();
    EXPECT_EQ(attributes->at("wavelit:passes"), "0:8");
    EXPECT_EQ(attributes->at("wavelit:passCount"), "8");
    EXPECT_EQ(attributes->at("wavelit:firstPass"), "0");
    EXPECT_EQ(attributes->at("wavelit:tracer"), device);
    auto single = scene::readExrAttributes(scene.file("whole.exr"));
    ASSERT_TRUE(single.ok());
    EXPECT_EQ(attributes->at("wavelit:sceneDigest"), single->at("wavelit:sceneDigest"));
    auto part = scene::readExrAttributes(scene.file("b.exr"));
    ASSERT_TRUE(part.ok());
    EXPECT_EQ(part->at("wavelit:passes"), "3:5");
    EXPECT_EQ(part->at("wavelit:firstPass"), "3");
}

TEST(PartialMerge, CpuPartsMergeIntoTheSingleRender) {
    expectMergeEqualsOneRender("cpu");
}

TEST(PartialMerge, VulkanPartsMergeIntoTheSingleRender) {
    expectMergeEqualsOneRender("vulkan");
}

// A merged file is a part again: (0:3 + 3:5) + 8:2 is the render of passes 0..9, and a plain
// render (passes 0..7) continues with --passes 8:2.
TEST(PartialMerge, MergedFilesAndPlainRendersMergeAgain) {
    TempScene scene("partial_merge_again");
    const std::string flags = " --width 8 --height 8 --seed 2 --sampler mis --device cpu";
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o whole.exr --spp 10" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o first8.exr --spp 8" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o a.exr --passes 0:3" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o b.exr --passes 3:5" + flags), 0);
    ASSERT_EQ(scene.cli("render " + scene.path() + " -o c.exr --passes 8:2" + flags), 0);
    ASSERT_EQ(scene.cli("merge a.exr b.exr -o ab.exr"), 0);
    ASSERT_EQ(scene.cli("merge ab.exr c.exr -o abc.exr"), 0);
    ASSERT_EQ(scene.cli("merge first8.exr c.exr -o continued.exr"), 0);
    const util::ImageRGB whole = scene.image("whole.exr");
    EXPECT_LE(worstRelative(scene.image("abc.exr"), whole), 1e-5);
    EXPECT_LE(worstRelative(scene.image("continued.exr"), whole), 1e-5);
    auto attributes = scene::readExrAttributes(scene.file("abc.exr"));
    ASSERT_TRUE(attributes.ok());
    EXPECT_EQ(attributes->at("wavelit:passes"), "0:10");
}

} // namespace
} // namespace wavelit
