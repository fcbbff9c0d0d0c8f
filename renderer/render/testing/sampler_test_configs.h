// The six shading configurations every direction sampler is judged at (issue 6 acceptance:
// grazing view at 85 degrees, a mirror-like r = 0.02 lobe, rough and diffuse ones), on a tilted
// frame so nothing lines up with the world or map axes by accident. Shared by the CPU sampler tests
// (direction_sampler_test.cpp) and the Vulkan ones (gpu_product_sampler_test.cpp), so both judge
// the same cases. Header-only; tests only.
#pragma once

#include "render/sampling/direction_sampler.h"
#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>

namespace wavelit::render::testing_configs {

struct Config {
    const char* name;
    const char* brdf;
    float roughness;
    float thetaOutDeg;
};

inline constexpr int kConfigs = 6;
inline constexpr Config kConfigList[kConfigs] = {
    {"normal view", "ggx", 0.5f, 0.0f},   {"grazing 85", "ggx", 0.3f, 85.0f},
    {"mirror r0.02", "ggx", 0.02f, 45.0f}, {"glossy r0.2", "ggx", 0.2f, 45.0f},
    {"rough r1", "ggx", 1.0f, 30.0f},      {"lambert", "lambert", 0.5f, 40.0f},
};

inline ShadingPoint shadingPoint(const Config& c, size_t material) {
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.85f, 0.4f));
    const util::Frame f = util::Frame::fromNormal(n);
    const float th = c.thetaOutDeg * (util::kPi / 180.0f), ph = 0.7f;
    const glm::vec3 wo = f.toWorld({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                    std::cos(th)});
    return {f.n, f.t, f.b, glm::normalize(wo), material};
}

inline glm::vec3 reflectionOf(const ShadingPoint& p) {
    return 2.0f * glm::dot(p.wo, p.n) * p.n - p.wo;
}

} // namespace wavelit::render::testing_configs
