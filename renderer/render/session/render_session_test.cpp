// RenderSession end to end on the bundled default scene (architecture.md §6 file -> Vulkan image):
// finite, not black, zero validation messages; plus the session's option checks.
#include "render/session/render_session.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "render/sampling/direction_sampler.h"
#include "scene/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace wavelit::render {
namespace {

const std::string kDefaultScene =
    std::string(WAVELIT_RESOURCE_DIR) + "/scenes/ring_on_ground.wlscene";

RenderOptions smallVulkan() {
    RenderOptions o;
    o.width = 64;
    o.height = 64;
    o.seed = 3;
    o.device = DeviceChoice::Vulkan;
    o.validation = true;
    return o;
}

TEST(RenderSession, DefaultSceneRendersOnVulkanWithoutValidationMessages) {
    if (!std::filesystem::exists(kDefaultScene))
        GTEST_SKIP() << kDefaultScene << " not present";
    auto scene = scene::loadScene(kDefaultScene);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto session = RenderSession::create(*scene, smallVulkan());
    ASSERT_TRUE(session.ok()) << session.error().message();
    constexpr int kPasses = 4;
    for (int i = 0; i < kPasses; ++i)
        ASSERT_TRUE((*session)->renderPass().ok());
    auto img = (*session)->image();
    ASSERT_TRUE(img.ok());
    double sum = 0.0;
    int lit = 0;
    for (const auto& p : img->pixels) {
        ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
        sum += util::luminance(p);
        if (util::luminance(p) > 0.0f)
            ++lit;
    }
    RenderStats stats = (*session)->stats();
    std::printf("default scene: mean %.4f, %d/%zu non-black pixels, device %s, bvh %.1f ms, "
                "upload %.1f ms, pipeline %.1f ms, passes %.1f ms\n",
                sum / img->pixels.size(), lit, img->pixels.size(), stats.deviceName.c_str(),
                stats.timings.bvhBuildSeconds * 1e3, stats.timings.uploadSeconds * 1e3,
                stats.timings.pipelineSeconds * 1e3, stats.timings.passSeconds * 1e3);
    EXPECT_GT(sum, 0.0);
    EXPECT_GT(lit, int(img->pixels.size() / 2)); // the environment lights most pixels
    EXPECT_EQ(stats.samplesPerPixel, kPasses);
    EXPECT_EQ(stats.validationMessages, 0);
    EXPECT_NE(stats.deviceName.find("vulkan"), std::string::npos);
}

TEST(RenderSession, EverySamplerRunsOnVulkan) {
    scene::Material mat;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 8, 4);
    RenderOptions o = smallVulkan();
    for (SamplerKind kind : allSamplerKinds()) {
        o.sampler = kind;
        auto onGpu = RenderSession::create(*scene, o);
        ASSERT_TRUE(onGpu.ok()) << samplerKindName(kind) << ": " << onGpu.error().message();
        ASSERT_TRUE((*onGpu)->renderPass().ok());
        EXPECT_NE((*onGpu)->stats().deviceName.find("vulkan"), std::string::npos);
        EXPECT_EQ((*onGpu)->stats().validationMessages, 0) << samplerKindName(kind);
    }
}

TEST(RenderSession, AutoFallsBackToCpuOnlyWithoutAUsableVulkanDevice) {
    scene::Material mat;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 8, 4);
    RenderOptions o = smallVulkan();
    o.device = DeviceChoice::Auto;
    o.width = o.height = 8;
    auto onVulkan = RenderSession::create(*scene, o);
    ASSERT_TRUE(onVulkan.ok()) << onVulkan.error().message();
    EXPECT_NE((*onVulkan)->stats().deviceName.find("vulkan"), std::string::npos);
    o.vulkanDevice = "no-such-device-xyz"; // no device matches: the CPU tracer takes over
    auto fallback = RenderSession::create(*scene, o);
    ASSERT_TRUE(fallback.ok()) << fallback.error().message();
    EXPECT_EQ((*fallback)->stats().deviceName.find("vulkan"), std::string::npos);
    o.device = DeviceChoice::Vulkan; // asked for explicitly: an error naming the device
    auto refused = RenderSession::create(*scene, o);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message().find("no-such-device-xyz"), std::string::npos);
}

// The Vulkan tracer submits a pass in pieces and polls the interrupt check between them (the
// editor's quit and request path, issue 19): an interrupted pass leaves samplesPerPixel as it was,
// the next renderPass resumes it, and the image is the uninterrupted one bit for bit; a reset
// drops an unfinished pass.
TEST(RenderSession, InterruptedPassesResumeToTheSameImage) {
    if (!std::filesystem::exists(kDefaultScene))
        GTEST_SKIP() << kDefaultScene << " not present";
    auto scene = scene::loadScene(kDefaultScene);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    RenderOptions o = smallVulkan();
    o.width = 160; // 10 x 6 tiles of 16 x 16 pixels
    o.height = 96;
    o.sampler = SamplerKind::Bsdf;
    constexpr int kPasses = 3;

    auto plain = RenderSession::create(*scene, o);
    ASSERT_TRUE(plain.ok()) << plain.error().message();
    for (int i = 0; i < kPasses; ++i)
        ASSERT_TRUE((*plain)->renderPass().ok());
    auto expected = (*plain)->image();
    ASSERT_TRUE(expected.ok());

    auto pieced = RenderSession::create(*scene, o);
    ASSERT_TRUE(pieced.ok()) << pieced.error().message();
    int polls = 0;
    (*pieced)->setInterruptCheck([&] { return ++polls % 2 == 0; }); // stop after every piece
    int interrupted = 0;
    while ((*pieced)->samplesPerPixel() < kPasses) {
        const int before = (*pieced)->samplesPerPixel();
        ASSERT_TRUE((*pieced)->renderPass().ok());
        if ((*pieced)->samplesPerPixel() == before)
            ++interrupted;
        else
            EXPECT_EQ((*pieced)->samplesPerPixel(), before + 1);
        ASSERT_LT(interrupted, 10000);
    }
    // The first pass at least is pieced: 4 tiles first, then at most doubling: 4 + 8 + 16 + 32.
    EXPECT_GE(interrupted, 3);
    auto image = (*pieced)->image();
    ASSERT_TRUE(image.ok());
    ASSERT_EQ(image->pixels.size(), expected->pixels.size());
    for (size_t i = 0; i < image->pixels.size(); ++i)
        ASSERT_EQ(image->pixels[i], expected->pixels[i]) << "pixel " << i;

    EXPECT_EQ((*pieced)->stats().validationMessages, 0);

    // Interrupt a first pass after its first piece, reset: the next full pass is a first pass
    // again, as in a session that never had the unfinished one.
    auto partial = RenderSession::create(*scene, o);
    ASSERT_TRUE(partial.ok()) << partial.error().message();
    polls = 0;
    (*partial)->setInterruptCheck([&] { return ++polls % 2 == 0; });
    ASSERT_TRUE((*partial)->renderPass().ok());
    EXPECT_EQ((*partial)->samplesPerPixel(), 0);
    (*partial)->resetAccumulation();
    (*partial)->setInterruptCheck(nullptr);
    ASSERT_TRUE((*partial)->renderPass().ok());
    EXPECT_EQ((*partial)->samplesPerPixel(), 1);
    auto fresh = RenderSession::create(*scene, o);
    ASSERT_TRUE(fresh.ok());
    ASSERT_TRUE((*fresh)->renderPass().ok());
    auto once = (*partial)->image(), onceFresh = (*fresh)->image();
    ASSERT_TRUE(once.ok() && onceFresh.ok());
    for (size_t i = 0; i < once->pixels.size(); ++i)
        ASSERT_EQ(once->pixels[i], onceFresh->pixels[i]) << "pixel " << i;
}

TEST(RenderSession, SetSceneRestartsWithTheNewScene) {
    scene::Material mat;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 8, 4);
    RenderOptions o = smallVulkan();
    o.width = o.height = 8;
    o.bounces = 1;
    auto session = RenderSession::create(*scene, o);
    ASSERT_TRUE(session.ok()) << session.error().message();
    ASSERT_TRUE((*session)->renderPass().ok());
    const double pipelineSeconds = (*session)->stats().timings.pipelineSeconds;
    scene->lighting.environment.intensity = 4.0f;
    scene->objects.clear();
    ASSERT_TRUE((*session)->setScene(*scene).ok());
    EXPECT_EQ((*session)->samplesPerPixel(), 0);
    ASSERT_TRUE((*session)->renderPass().ok());
    auto img = (*session)->image();
    ASSERT_TRUE(img.ok());
    for (const auto& p : img->pixels) ASSERT_EQ(p, glm::vec3(4.0f));
    // The Vulkan integrator swapped its buffers instead of recompiling its pipeline.
    EXPECT_EQ((*session)->stats().timings.pipelineSeconds, pipelineSeconds);
    EXPECT_EQ((*session)->stats().validationMessages, 0);
}

TEST(RenderSession, CpuDeviceAndResetWork) {
    scene::Material mat;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 8, 4);
    RenderOptions o = smallVulkan();
    o.device = DeviceChoice::Cpu;
    o.width = o.height = 16;
    auto session = RenderSession::create(*scene, o);
    ASSERT_TRUE(session.ok()) << session.error().message();
    ASSERT_TRUE((*session)->renderPass().ok());
    EXPECT_EQ((*session)->samplesPerPixel(), 1);
    (*session)->resetAccumulation();
    EXPECT_EQ((*session)->samplesPerPixel(), 0);
    EXPECT_EQ((*session)->stats().validationMessages, 0);
}

} // namespace
} // namespace wavelit::render
