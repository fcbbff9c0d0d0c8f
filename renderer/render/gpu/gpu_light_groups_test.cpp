// The Vulkan tracer's LightMix layers (shaders/common/light_groups.glsl, gpu_path_tracer_groups.cpp):
// they sum to the beauty to float rounding on every bundled scene with every sampler (one pipeline
// per sampler, scenes swapped in with setScene: this also covers the group buffers' resizing when
// the number of groups changes), and each layer matches the CPU reference's layer path for path
// on shared random streams (as MatchesCpuReferenceWithTheSameRandomStreams does for the beauty);
// zero validation messages. A layer plan beyond the device's storage-buffer range is refused with
// a message naming the light groups.
#include "render/gpu/render_limits.h"
#include "render/session/light_groups.h"
#include "render/session/render_session.h"
#include "render/testing/light_group_scenes.h"

#include <gtest/gtest.h>

namespace wavelit::render {
namespace {

RenderOptions vulkanGroups(SamplerKind kind) {
    RenderOptions o;
    o.width = 16;
    o.height = 12;
    o.bounces = 3;
    o.seed = 5;
    o.sampler = kind;
    o.device = DeviceChoice::Vulkan;
    o.validation = true;
    o.lightGroups = true;
    return o;
}

TEST(GpuLightGroups, LayersSumToTheBeautyOnEveryBundledSceneAndSampler) {
    const std::vector<NamedScene> scenes = lightMixScenes();
    ASSERT_EQ(scenes.size(), 6u);
    for (SamplerKind kind : {SamplerKind::Uniform, SamplerKind::Cosine, SamplerKind::Bsdf,
                             SamplerKind::Env, SamplerKind::Mis, SamplerKind::Wavelet,
                             SamplerKind::Oracle}) {
        std::unique_ptr<RenderSession> session;
        for (const NamedScene& s : scenes) {
            const std::string what = s.name + " / " + samplerKindName(kind);
            if (!session) {
                auto created = RenderSession::create(s.scene, vulkanGroups(kind));
                ASSERT_TRUE(created.ok()) << what << ": " << created.error().message();
                session = std::move(created.value());
            } else {
                ASSERT_TRUE(session->setScene(s.scene).ok()) << what;
            }
            for (int pass = 0; pass < 2; ++pass) ASSERT_TRUE(session->renderPass().ok()) << what;
            auto beauty = session->image();
            auto layers = session->groupImages();
            ASSERT_TRUE(beauty.ok() && layers.ok()) << what;
            ASSERT_EQ(layers->size(), session->lightGroups().size()) << what;
            expectLayersSumToBeauty(*beauty, *layers, what);
        }
        EXPECT_EQ(session->stats().validationMessages, 0) << samplerKindName(kind);
        EXPECT_NE(session->stats().deviceName.find("vulkan"), std::string::npos);
    }
}

// Same draws, same layers: per layer, at most a few per cent of pixels differ beyond rounding
// (paths that a rounding difference sends another way), and the layer means agree.
TEST(GpuLightGroups, LayersMatchTheCpuReferencePathForPath) {
    std::vector<NamedScene> scenes = lightMixScenes();
    ASSERT_EQ(scenes.size(), 6u);
    const scene::Scene& night = scenes[4].scene; // ring_on_ground+night_emissive: 3 light types
    for (SamplerKind kind : {SamplerKind::Bsdf, SamplerKind::Mis}) {
        RenderOptions gpuOptions = vulkanGroups(kind);
        gpuOptions.width = 32;
        gpuOptions.height = 24;
        RenderOptions cpuOptions = gpuOptions;
        cpuOptions.device = DeviceChoice::Cpu;
        auto gpu = RenderSession::create(night, gpuOptions);
        auto cpu = RenderSession::create(night, cpuOptions);
        ASSERT_TRUE(gpu.ok() && cpu.ok());
        for (int pass = 0; pass < 2; ++pass) {
            ASSERT_TRUE((*gpu)->renderPass().ok());
            ASSERT_TRUE((*cpu)->renderPass().ok());
        }
        auto g = (*gpu)->groupImages();
        auto c = (*cpu)->groupImages();
        ASSERT_TRUE(g.ok() && c.ok());
        ASSERT_EQ(g->size(), c->size());
        const LightGroups groups = (*cpu)->lightGroups();
        for (size_t layer = 0; layer < g->size(); ++layer) {
            int differing = 0;
            double gm = 0.0, cm = 0.0;
            for (size_t i = 0; i < (*g)[layer].pixels.size(); ++i) {
                const glm::vec3 a = (*g)[layer].pixels[i], b = (*c)[layer].pixels[i];
                const glm::vec3 d = glm::abs(a - b);
                const float scale = std::max(1e-3f, util::luminance(b));
                if (std::max(d.r, std::max(d.g, d.b)) > 1e-3f * scale + 1e-5f) ++differing;
                gm += util::luminance(a);
                cm += util::luminance(b);
            }
            const std::string what = groups.names[layer] + " / " + samplerKindName(kind);
            std::printf("layer %s: cpu mean %.5f, gpu mean %.5f, %d of %zu pixels differ\n",
                        what.c_str(), cm, gm, differing, (*g)[layer].pixels.size());
            EXPECT_LT(differing, int((*g)[layer].pixels.size() / 20)) << what;
            EXPECT_NEAR(gm, cm, 0.02 * cm + 1e-6) << what;
        }
        EXPECT_EQ((*gpu)->stats().validationMessages, 0);
    }
}

TEST(GpuLightGroups, LayersBeyondTheStorageBufferRangeAreRefusedNamingTheGroups) {
    GpuMemoryPlan plan;
    plan.width = 2048;
    plan.height = 2048;
    plan.buffers.push_back(gpuAccumulationPlan(2048, 2048));
    plan.buffers.push_back(gpuLightGroupPlan(5, 2048, 2048));
    GpuDeviceLimits limits;
    limits.deviceName = "test device";
    limits.maxStorageBufferRange = uint64_t(128) << 20;
    auto status = checkGpuMemoryPlan(plan, limits);
    ASSERT_FALSE(status.ok());
    const std::string message = status.error().message();
    EXPECT_NE(message.find("--light-groups (5 layers of 2048x2048"), std::string::npos) << message;
    EXPECT_NE(message.find("240.0 MiB"), std::string::npos) << message; // 5 x 2048^2 x 12 bytes
    EXPECT_NE(message.find("`group` property"), std::string::npos) << message;
}

} // namespace
} // namespace wavelit::render
