#include "render/session/light_remix.h"

#include "scene/scene_compare.h"

#include <algorithm>
#include <cmath>

namespace wavelit::render {
namespace {

glm::vec3 emitted(const scene::Light& l) {
    return l.muted ? glm::vec3(0.0f) : l.color * l.intensity;
}

// shown / rendered per channel; nullopt where rendered is 0 but shown is not.
std::optional<glm::vec3> ratio(const glm::vec3& rendered, const glm::vec3& shown) {
    glm::vec3 r(0.0f);
    for (int c = 0; c < 3; ++c) {
        if (rendered[c] > 0.0f)
            r[c] = shown[c] / rendered[c];
        else if (shown[c] > 0.0f)
            return std::nullopt;
    }
    return r;
}

// One group's weight from two of its lights: equal up to float rounding (an editor scales a
// group's members by one factor, each product rounded on its own).
bool sameWeight(const glm::vec3& a, const glm::vec3& b) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a[c] - b[c]) > 1e-5f * std::max(std::abs(a[c]), std::abs(b[c]))) return false;
    return true;
}

} // namespace

std::optional<std::vector<glm::vec3>> remixWeights(const scene::Scene& rendered,
                                                   const scene::Scene& shown) {
    if (rendered.lighting.lights.size() != shown.lighting.lights.size()) return std::nullopt;
    // Everything but the remixable values must be equal.
    scene::Scene same = shown;
    for (size_t i = 0; i < same.lighting.lights.size(); ++i) {
        const scene::Light& r = rendered.lighting.lights[i];
        scene::Light& s = same.lighting.lights[i];
        s.intensity = r.intensity;
        s.color = r.color;
        s.muted = r.muted;
    }
    same.lighting.environment.intensity = rendered.lighting.environment.intensity;
    if (!scene::firstDifference(same, rendered).empty()) return std::nullopt;

    const LightGroups groups = lightGroupsOf(rendered);
    std::vector<glm::vec3> weights(groups.size(), glm::vec3(1.0f));
    std::vector<bool> set(groups.size(), false);
    for (size_t i = 0; i < rendered.lighting.lights.size(); ++i) {
        auto w = ratio(emitted(rendered.lighting.lights[i]), emitted(shown.lighting.lights[i]));
        if (!w) return std::nullopt;
        const size_t g = size_t(groups.groupOfLight[i]);
        if (set[g] && !sameWeight(weights[g], *w)) return std::nullopt; // a group scaled unevenly
        weights[g] = *w;
        set[g] = true;
    }
    const scene::Environment& re = rendered.lighting.environment;
    const scene::Environment& se = shown.lighting.environment;
    auto env = ratio(glm::vec3(re.intensity), glm::vec3(se.intensity));
    if (!env) return std::nullopt;
    const size_t g = size_t(groups.environmentGroup);
    if (set[g] && !sameWeight(weights[g], *env)) return std::nullopt; // a light grouped with the environment
    weights[g] = *env;
    return weights;
}

scene::Scene remixBaseScene(const scene::Scene& shown) {
    scene::Scene base = shown;
    for (scene::Light& l : base.lighting.lights) l.muted = false;
    return base;
}

} // namespace wavelit::render
