// Scenes for the LightMix tests (light groups, mixes, solos): every bundled scene, the default
// scene under each bundled lighting setup (every light type), and the Cornell box with an emissive
// material (the `emission` group). Header-only; tests only.
#pragma once

#include "scene/scene.h"
#include "scene/scene_io.h"
#include "util/image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace wavelit::render {

struct NamedScene {
    std::string name;
    scene::Scene scene;
};

inline std::string lightMixResource(const std::string& relative) {
    return std::string(WAVELIT_RESOURCE_DIR) + "/" + relative;
}

// Fails the calling test (ADD_FAILURE) for a file that does not load; returns what loaded.
inline std::vector<NamedScene> lightMixScenes() {
    std::vector<NamedScene> out;
    for (const char* name : {"ring_on_ground", "glossy_sphere", "cornell_box"}) {
        const std::string path = lightMixResource(std::string("scenes/") + name + ".wlscene");
        auto s = scene::loadScene(path);
        if (!s) {
            ADD_FAILURE() << s.error().message();
            continue;
        }
        out.push_back({name, std::move(*s)});
    }
    const std::string ring = lightMixResource("scenes/ring_on_ground.wlscene");
    for (const char* lighting : {"sun_sky", "night_emissive"}) {
        auto s = scene::loadScene(ring);
        if (!s) continue;
        auto attached = scene::attachLightingSetup(
            *s, ring, lightMixResource(std::string("lighting/") + lighting + ".wllight"));
        if (!attached) {
            ADD_FAILURE() << attached.error().message();
            continue;
        }
        out.push_back({std::string("ring_on_ground+") + lighting, std::move(*s)});
    }
    auto box = scene::loadScene(lightMixResource("scenes/cornell_box.wlscene"));
    if (box && !box->materials.empty()) {
        box->materials.back().emission = glm::vec3(0.8f, 0.6f, 0.3f);
        out.push_back({"cornell_box+emissive", std::move(*box)});
    }
    return out;
}

// Checks Σ layers == beauty per pixel and channel to float rounding (relative to the summed
// magnitudes), and that no layer has a NaN; `what` names the case in messages.
inline void expectLayersSumToBeauty(const util::ImageRGB& beauty,
                                    const std::vector<util::ImageRGB>& layers,
                                    const std::string& what) {
    ASSERT_FALSE(layers.empty()) << what;
    int bad = 0;
    double worst = 0.0;
    for (size_t p = 0; p < beauty.pixels.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0, magnitude = std::abs(double(beauty.pixels[p][c]));
            for (const util::ImageRGB& layer : layers) {
                ASSERT_EQ(layer.pixels.size(), beauty.pixels.size()) << what;
                ASSERT_TRUE(std::isfinite(layer.pixels[p][c])) << what;
                sum += layer.pixels[p][c];
                magnitude += std::abs(double(layer.pixels[p][c]));
            }
            const double error = std::abs(sum - double(beauty.pixels[p][c]));
            worst = std::max(worst, error / std::max(magnitude, 1e-30));
            if (error > 1e-5 * magnitude + 1e-7) ++bad;
        }
    EXPECT_EQ(bad, 0) << what << ": worst relative error " << worst;
}

} // namespace wavelit::render
