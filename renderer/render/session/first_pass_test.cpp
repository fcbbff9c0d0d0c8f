// RenderOptions::firstPass (docs/estimator.md "Random numbers"): a render of passes 3..7 is the
// second part of a render of passes 0..7, on either tracer, so parts of disjoint pass ranges
// merge into the longer render (`wavelit-cli merge`, docs/farm.md).
#include "render/session/render_session.h"

#include "scene/scene_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wavelit::render {
namespace {

const std::string kScene = std::string(WAVELIT_RESOURCE_DIR) + "/scenes/ring_on_ground.wlscene";

util::ImageRGB render(const scene::Scene& scene, DeviceChoice device, int firstPass, int passes) {
    RenderOptions o;
    o.width = 16;
    o.height = 12;
    o.seed = 7;
    o.sampler = SamplerKind::Mis; // env NEE, BSDF continuation and MIS: every draw site
    o.device = device;
    o.validation = true;
    o.firstPass = firstPass;
    auto session = RenderSession::create(scene, o);
    EXPECT_TRUE(session.ok()) << session.error().message();
    if (!session) return {};
    for (int i = 0; i < passes; ++i) EXPECT_TRUE((*session)->renderPass().ok());
    EXPECT_EQ((*session)->samplesPerPixel(), passes);
    EXPECT_EQ((*session)->stats().validationMessages, 0);
    auto image = (*session)->image();
    EXPECT_TRUE(image.ok());
    return image.ok() ? *image : util::ImageRGB{};
}

void expectPartsMakeTheWhole(DeviceChoice device) {
    auto scene = scene::loadScene(kScene);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const util::ImageRGB whole = render(*scene, device, 0, 8);
    const util::ImageRGB head = render(*scene, device, 0, 3);
    const util::ImageRGB tail = render(*scene, device, 3, 5);
    const util::ImageRGB tailFromZero = render(*scene, device, 0, 5);
    ASSERT_EQ(whole.pixels.size(), size_t(16 * 12));
    ASSERT_EQ(tail.pixels.size(), whole.pixels.size());
    double worst = 0.0;
    int differs = 0;
    for (size_t i = 0; i < whole.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double w = whole.pixels[i][c];
            const double merged = (3.0 * head.pixels[i][c] + 5.0 * tail.pixels[i][c]) / 8.0;
            worst = std::max(worst, std::abs(merged - w) / std::max(std::abs(w), 1e-6));
            differs += tail.pixels[i][c] != tailFromZero.pixels[i][c];
        }
    std::printf("worst relative difference %.3g\n", worst);
    EXPECT_LE(worst, 1e-5) << "passes 0..2 + 3..7 differ from passes 0..7";
    // The offset reaches the random numbers: passes 3..7 are not passes 0..4 again.
    EXPECT_GT(differs, int(whole.pixels.size()));
}

TEST(FirstPass, CpuPartsOfDisjointPassRangesMakeTheWholeRender) {
    expectPartsMakeTheWhole(DeviceChoice::Cpu);
}

TEST(FirstPass, VulkanPartsOfDisjointPassRangesMakeTheWholeRender) {
    expectPartsMakeTheWhole(DeviceChoice::Vulkan);
}

} // namespace
} // namespace wavelit::render
