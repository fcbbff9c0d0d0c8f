// LightMix light groups (light_groups.h, docs/lightmix.md): which layer each emitter goes to, and
// on the CPU reference tracer that the layers sum to the beauty to float rounding on every
// bundled scene (and every light type and an emissive material) with every sampler. The Vulkan
// tracer's twin: render/gpu/gpu_light_groups_test.cpp.
#include "render/session/light_groups.h"

#include "render/session/render_session.h"
#include "render/testing/light_group_scenes.h"

#include <gtest/gtest.h>

namespace wavelit::render {
namespace {

scene::Light light(const std::string& name, const std::string& group = "") {
    scene::Light l;
    l.name = name;
    l.group = group;
    return l;
}

TEST(LightGroups, OneLayerPerLightThenEnvironmentThenEmission) {
    scene::Scene s;
    s.lighting.lights = {light("key"), light("fill"), light("rim")};
    LightGroups g = lightGroupsOf(s);
    EXPECT_EQ(g.names, (std::vector<std::string>{"key", "fill", "rim", "environment"}));
    EXPECT_EQ(g.groupOfLight, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(g.environmentGroup, 3);
    EXPECT_EQ(g.emissionGroup, -1); // nothing emits: no layer (model only what a scene needs)

    scene::Material glow;
    glow.id = 7;
    glow.emission = glm::vec3(1.0f);
    s.materials.push_back(glow);
    scene::Object o;
    o.materialId = 7;
    s.objects.push_back(o);
    g = lightGroupsOf(s);
    EXPECT_EQ(g.names.back(), "emission");
    EXPECT_EQ(g.emissionGroup, 4);
}

TEST(LightGroups, GroupPropertyMergesLightsAndUnnamedLightsGetTheirId) {
    scene::Scene s;
    s.lighting.lights = {light("a", "practicals"), light("sun"), light("b", "practicals"),
                         light("", "")};
    s.lighting.lights[3].id = 9;
    const LightGroups g = lightGroupsOf(s);
    EXPECT_EQ(g.names,
              (std::vector<std::string>{"practicals", "sun", "light-9", "environment"}));
    EXPECT_EQ(g.groupOfLight, (std::vector<int>{0, 1, 0, 2}));
}

TEST(LightGroups, MixWeightsEachLayer) {
    util::ImageRGB a(2, 1, glm::vec3(1.0f, 2.0f, 3.0f)), b(2, 1, glm::vec3(0.5f));
    const util::ImageRGB m = mixGroupLayers({a, b}, {glm::vec3(2.0f, 0.0f, 1.0f)});
    EXPECT_EQ(m.pixels[1], glm::vec3(2.5f, 0.5f, 3.5f)); // b's missing weight counts as 1
    EXPECT_EQ(lightGroupLayerBytes(3, 512, 512), 3ull * 512 * 512 * 12);
}

TEST(LightGroups, NoLayersUnlessRequested) {
    auto scenes = lightMixScenes();
    ASSERT_FALSE(scenes.empty());
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    o.device = DeviceChoice::Cpu;
    auto session = RenderSession::create(scenes[0].scene, o);
    ASSERT_TRUE(session.ok()) << session.error().message();
    ASSERT_TRUE((*session)->renderPass().ok());
    auto layers = (*session)->groupImages();
    ASSERT_TRUE(layers.ok());
    EXPECT_TRUE(layers->empty());
}

// Every scene x every sampler, one pass at 16x12 (two for `bsdf`, the accumulation over passes).
TEST(LightGroups, CpuLayersSumToTheBeautyOnEveryBundledSceneAndSampler) {
    const std::vector<NamedScene> scenes = lightMixScenes();
    ASSERT_EQ(scenes.size(), 6u);
    for (SamplerKind kind : {SamplerKind::Uniform, SamplerKind::Cosine, SamplerKind::Bsdf,
                             SamplerKind::Env, SamplerKind::Mis, SamplerKind::Wavelet,
                             SamplerKind::Oracle}) {
        RenderOptions o;
        o.width = 16;
        o.height = 12;
        o.bounces = 3;
        o.seed = 5;
        o.sampler = kind;
        o.device = DeviceChoice::Cpu;
        o.lightGroups = true;
        std::unique_ptr<RenderSession> session;
        for (const NamedScene& s : scenes) {
            const std::string what = s.name + " / " + samplerKindName(kind);
            if (!session) {
                auto created = RenderSession::create(s.scene, o);
                ASSERT_TRUE(created.ok()) << what << ": " << created.error().message();
                session = std::move(created.value());
            } else {
                ASSERT_TRUE(session->setScene(s.scene).ok()) << what;
            }
            for (int pass = 0; pass < (kind == SamplerKind::Bsdf ? 2 : 1); ++pass)
                ASSERT_TRUE(session->renderPass().ok()) << what;
            auto beauty = session->image();
            auto layers = session->groupImages();
            ASSERT_TRUE(beauty.ok() && layers.ok()) << what;
            const LightGroups groups = session->lightGroups();
            ASSERT_EQ(layers->size(), groups.size()) << what;
            expectLayersSumToBeauty(*beauty, *layers, what);
            // Every light and the emission put something in their layer somewhere (else the
            // test could pass with everything in one layer).
            for (size_t g = 0; g < groups.size(); ++g) {
                if (int(g) == groups.environmentGroup) continue;
                double total = 0.0;
                for (const glm::vec3& p : (*layers)[g].pixels) total += p.r + p.g + p.b;
                EXPECT_GT(total, 0.0) << what << ": layer " << groups.names[g] << " is black";
            }
        }
    }
}

} // namespace
} // namespace wavelit::render
