// remixWeights (light_remix.h): which edits a LightMix remix can show, with which weights, and a
// remix of a muted-then-unmuted light matching a fresh render of the unmuted scene path for path.
#include "render/session/light_remix.h"

#include "render/session/render_session.h"
#include "render/testing/light_group_scenes.h"

#include <gtest/gtest.h>

namespace wavelit::render {
namespace {

scene::Scene twoLights() {
    scene::Scene s;
    scene::Light a, b;
    a.name = "key";
    a.intensity = 10.0f;
    a.color = glm::vec3(1.0f, 0.5f, 0.25f);
    b.name = "fill";
    b.intensity = 4.0f;
    s.lighting.lights = {a, b};
    s.lighting.environment.intensity = 2.0f;
    return s;
}

TEST(LightRemix, IntensityColourMuteAndEnvironmentIntensityAreWeights) {
    const scene::Scene rendered = twoLights();
    scene::Scene shown = rendered;
    shown.lighting.lights[0].intensity = 20.0f;
    shown.lighting.lights[0].color = glm::vec3(1.0f, 1.0f, 0.25f);
    shown.lighting.lights[1].muted = true;
    shown.lighting.environment.intensity = 1.0f;
    auto w = remixWeights(rendered, shown);
    ASSERT_TRUE(w.has_value());
    ASSERT_EQ(w->size(), 3u); // key, fill, environment
    EXPECT_EQ((*w)[0], glm::vec3(2.0f, 4.0f, 2.0f));
    EXPECT_EQ((*w)[1], glm::vec3(0.0f));
    EXPECT_EQ((*w)[2], glm::vec3(0.5f));
    auto same = remixWeights(rendered, rendered);
    ASSERT_TRUE(same.has_value());
    for (const glm::vec3& x : *same) EXPECT_EQ(x, glm::vec3(1.0f));
}

TEST(LightRemix, EverythingElseRestarts) {
    const scene::Scene rendered = twoLights();
    scene::Scene moved = rendered;
    moved.lighting.lights[0].position.x += 1.0f;
    EXPECT_FALSE(remixWeights(rendered, moved).has_value());
    scene::Scene tinted = rendered;
    tinted.lighting.environment.tint = glm::vec3(1.0f, 0.5f, 0.5f);
    EXPECT_FALSE(remixWeights(rendered, tinted).has_value());
    scene::Scene added = rendered;
    added.lighting.lights.push_back(added.lighting.lights[0]);
    EXPECT_FALSE(remixWeights(rendered, added).has_value());
    // Up from black: no layer to scale.
    scene::Scene dark = rendered;
    dark.lighting.lights[1].intensity = 0.0f;
    EXPECT_FALSE(remixWeights(dark, rendered).has_value());
    // Lights of one group scaled by different factors.
    scene::Scene grouped = rendered;
    grouped.lighting.lights[0].group = grouped.lighting.lights[1].group = "both";
    scene::Scene uneven = grouped;
    uneven.lighting.lights[0].intensity *= 2.0f;
    EXPECT_FALSE(remixWeights(grouped, uneven).has_value());
    scene::Scene even = uneven;
    even.lighting.lights[1].intensity *= 2.0f;
    ASSERT_TRUE(remixWeights(grouped, even).has_value());
    EXPECT_EQ((*remixWeights(grouped, even))[0], glm::vec3(2.0f));
    // One factor applied to each member rounds on its own (an editor's group slider): still one
    // weight, within float rounding.
    grouped.lighting.lights[0].intensity = 60.0f;
    grouped.lighting.lights[1].intensity = 45.0f;
    scene::Scene third = grouped;
    bool roundingDiffers = false;
    for (float f : {1.0f / 3.0f, 0.7f, 1.0822f, 1.4384f, 12.9f}) {
        third.lighting.lights[0].intensity = 60.0f * f;
        third.lighting.lights[1].intensity = 45.0f * f;
        roundingDiffers |= third.lighting.lights[0].intensity / 60.0f != third.lighting.lights[1].intensity / 45.0f;
        auto w = remixWeights(grouped, third);
        ASSERT_TRUE(w.has_value()) << f;
        EXPECT_NEAR((*w)[0].x, f, 1e-5f * f);
    }
    EXPECT_TRUE(roundingDiffers); // the case the tolerance is for
}

// The editor renders remixBaseScene (every light unmuted) and shows the mix: the shown image of a
// muted light equals, path for path, a render of the scene with that light muted.
TEST(LightRemix, MutedLightRemixEqualsARenderOfTheMutedScene) {
    std::vector<NamedScene> scenes = lightMixScenes();
    ASSERT_EQ(scenes.size(), 6u);
    scene::Scene shown = scenes[4].scene; // night: window, lamp, spot, environment
    shown.lighting.lights[1].muted = true;
    shown.lighting.lights[0].intensity *= 3.0f;
    const scene::Scene base = remixBaseScene(shown);
    auto weights = remixWeights(base, shown);
    ASSERT_TRUE(weights.has_value());
    RenderOptions o;
    o.width = 24;
    o.height = 18;
    o.bounces = 2;
    o.sampler = SamplerKind::Mis;
    o.device = DeviceChoice::Cpu;
    o.lightGroups = true;
    auto layered = RenderSession::create(base, o);
    o.lightGroups = false;
    auto fresh = RenderSession::create(shown, o);
    ASSERT_TRUE(layered.ok() && fresh.ok());
    for (int pass = 0; pass < 4; ++pass) {
        ASSERT_TRUE((*layered)->renderPass().ok());
        ASSERT_TRUE((*fresh)->renderPass().ok());
    }
    const util::ImageRGB mixed = mixGroupLayers(*(*layered)->groupImages(), *weights);
    const util::ImageRGB reference = *(*fresh)->image();
    int differing = 0;
    for (size_t i = 0; i < mixed.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(mixed.pixels[i] - reference.pixels[i]);
        const float scale = std::max(1e-3f, util::luminance(reference.pixels[i]));
        if (std::max(d.r, std::max(d.g, d.b)) > 1e-4f * scale + 1e-6f) ++differing;
    }
    EXPECT_LE(differing, int(mixed.pixels.size() / 100));
}

} // namespace
} // namespace wavelit::render
