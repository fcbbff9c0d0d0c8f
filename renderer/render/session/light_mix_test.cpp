// LightMix against independent renders (docs/lightmix.md), on the CPU reference tracer:
// - a mix with new weights equals a render of the scene with those intensities and colours: path
//   for path with the same seed (light selection is uniform and the env tables are normalised, so
//   the draws do not depend on intensities), and within noise with another seed;
// - a solo (every other group weighted 0) equals a render with the other lights removed and the
//   environment black, within noise.
// "Within noise" is robust against the sun's fireflies (a plain RMSE swings by ±30% between
// seeds): the median over 4x4 blocks of |mean difference| is at most twice the larger of the
// seed-to-seed figures of the two estimators compared (mix vs mix, render vs render, each at two
// seeds), and the image means agree within 5%.
#include "render/testing/median_block_error.h"
#include "render/session/light_groups.h"
#include "render/session/render_session.h"
#include "render/testing/light_group_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace wavelit::render {
namespace {

constexpr int kWidth = 48, kHeight = 36, kPasses = 64;

RenderOptions cpuOptions(uint64_t seed, bool groups) {
    RenderOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.bounces = 3;
    o.seed = seed;
    o.sampler = SamplerKind::Mis;
    o.device = DeviceChoice::Cpu;
    o.lightGroups = groups;
    return o;
}

struct Rendered {
    util::ImageRGB beauty;
    std::vector<util::ImageRGB> layers;
    LightGroups groups;
};

Rendered render(const scene::Scene& scene, uint64_t seed, bool groups) {
    Rendered r;
    auto session = RenderSession::create(scene, cpuOptions(seed, groups));
    EXPECT_TRUE(session.ok()) << session.error().message();
    if (!session.ok()) return r;
    for (int pass = 0; pass < kPasses; ++pass) EXPECT_TRUE((*session)->renderPass().ok());
    r.beauty = *(*session)->image();
    r.layers = *(*session)->groupImages();
    r.groups = (*session)->lightGroups();
    return r;
}

// weights by group name; unnamed groups keep 1.
util::ImageRGB mix(const Rendered& r, const std::vector<std::pair<std::string, glm::vec3>>& named) {
    std::vector<glm::vec3> weights(r.groups.size(), glm::vec3(1.0f));
    for (const auto& [name, w] : named) {
        auto it = std::find(r.groups.names.begin(), r.groups.names.end(), name);
        EXPECT_NE(it, r.groups.names.end()) << name;
        if (it != r.groups.names.end()) weights[size_t(it - r.groups.names.begin())] = w;
    }
    return mixGroupLayers(r.layers, weights);
}

double meanLuminance(const util::ImageRGB& img) {
    double sum = 0.0;
    for (const glm::vec3& p : img.pixels) sum += util::luminance(p);
    return sum / double(img.pixels.size());
}

// mix1, mix2: the mixes of two seeds' layers; ref1, ref2: two seeds of the independent render.
void expectWithinNoise(const util::ImageRGB& mix1, const util::ImageRGB& mix2,
                       const util::ImageRGB& ref1, const util::ImageRGB& ref2,
                       const std::string& what) {
    const double seedToSeed = std::max(medianBlockError(mix1, mix2), medianBlockError(ref1, ref2));
    const double error = medianBlockError(mix1, ref1);
    const double mm = meanLuminance(mix1), rm = meanLuminance(ref1);
    std::printf("%s: median 4x4-block error %.5f, seed-to-seed %.5f; means %.5f vs %.5f\n",
                what.c_str(), error, seedToSeed, mm, rm);
    EXPECT_LE(error, 2.0 * seedToSeed) << what;
    EXPECT_GT(rm, 0.0) << what;
    EXPECT_NEAR(mm, rm, 0.05 * rm) << what;
}

scene::Light* findLight(scene::Scene& s, const std::string& name) {
    for (scene::Light& l : s.lighting.lights)
        if (l.name == name) return &l;
    ADD_FAILURE() << "no light " << name;
    return nullptr;
}

TEST(LightMix, NewWeightsEqualARenderWithThoseIntensities) {
    auto scene = scene::loadScene(lightMixResource("scenes/glossy_sphere.wlscene"));
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    // sun x (2, 1, 0.5) (intensity x 2, colour x (1, 0.5, 0.25)), environment x 0.5.
    const glm::vec3 sunWeight(2.0f, 1.0f, 0.5f);
    scene::Scene changed = *scene;
    scene::Light* sun = findLight(changed, "sun");
    ASSERT_NE(sun, nullptr);
    sun->intensity *= 2.0f;
    sun->color *= glm::vec3(1.0f, 0.5f, 0.25f);
    changed.lighting.environment.intensity *= 0.5f;
    const std::vector<std::pair<std::string, glm::vec3>> weights = {
        {"sun", sunWeight}, {"environment", glm::vec3(0.5f)}};

    const Rendered a = render(*scene, 1, true), b = render(*scene, 2, true);
    const util::ImageRGB mixA = mix(a, weights), mixB = mix(b, weights);
    const util::ImageRGB same = render(changed, 1, false).beauty;
    // The same draws: equal to float rounding, bar paths a rounding difference sends elsewhere.
    int differing = 0;
    for (size_t i = 0; i < same.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(mixA.pixels[i] - same.pixels[i]);
        const float scale = std::max(1e-3f, util::luminance(same.pixels[i]));
        if (std::max(d.r, std::max(d.g, d.b)) > 1e-4f * scale + 1e-6f) ++differing;
    }
    std::printf("mix vs render with the same seed: %d of %zu pixels differ\n", differing,
                same.pixels.size());
    EXPECT_LE(differing, int(same.pixels.size() / 100));
    // Independent seeds.
    expectWithinNoise(mixA, mixB, render(changed, 3, false).beauty,
                      render(changed, 4, false).beauty, "mix sun=2:1:0.5, environment=0.5");
}

TEST(LightMix, SoloEqualsARenderWithTheOtherLightsRemoved) {
    std::vector<NamedScene> scenes = lightMixScenes();
    ASSERT_EQ(scenes.size(), 6u);
    const scene::Scene& night = scenes[4].scene; // window (rect), lamp (sphere), spot, env
    const Rendered a = render(night, 1, true), b = render(night, 2, true);
    for (const std::string solo : {"lamp", "window"}) {
        std::vector<std::pair<std::string, glm::vec3>> weights;
        for (const std::string& name : a.groups.names)
            if (name != solo) weights.emplace_back(name, glm::vec3(0.0f));
        scene::Scene alone = night;
        alone.lighting.lights.erase(
            std::remove_if(alone.lighting.lights.begin(), alone.lighting.lights.end(),
                           [&](const scene::Light& l) { return l.name != solo; }),
            alone.lighting.lights.end());
        ASSERT_EQ(alone.lighting.lights.size(), 1u);
        alone.lighting.environment.intensity = 0.0f;
        expectWithinNoise(mix(a, weights), mix(b, weights), render(alone, 3, false).beauty,
                          render(alone, 4, false).beauty, "solo " + solo);
    }
}

} // namespace
} // namespace wavelit::render
