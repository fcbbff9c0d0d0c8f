#include "render/session/light_groups.h"

#include <algorithm>

namespace wavelit::render {
namespace {

int groupIndex(std::vector<std::string>& names, const std::string& name) {
    auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return int(it - names.begin());
    names.push_back(name);
    return int(names.size()) - 1;
}

bool anyObjectEmits(const scene::Scene& scene) {
    for (const scene::Object& object : scene.objects) {
        const scene::Material* m = scene.findMaterial(object.materialId);
        if (m && (m->emission.r > 0.0f || m->emission.g > 0.0f || m->emission.b > 0.0f))
            return true;
    }
    return false;
}

} // namespace

std::string lightGroupName(const scene::Light& light) {
    if (!light.group.empty()) return light.group;
    if (!light.name.empty()) return light.name;
    return "light-" + std::to_string(light.id);
}

LightGroups lightGroupsOf(const scene::Scene& scene) {
    LightGroups g;
    for (const scene::Light& light : scene.lighting.lights)
        g.groupOfLight.push_back(groupIndex(g.names, lightGroupName(light)));
    g.environmentGroup = groupIndex(g.names, kEnvironmentGroup);
    if (anyObjectEmits(scene)) g.emissionGroup = groupIndex(g.names, kEmissionGroup);
    return g;
}

util::ImageRGB mixGroupLayers(const std::vector<const util::ImageRGB*>& layers,
                              const std::vector<glm::vec3>& weights) {
    if (layers.empty()) return {};
    util::ImageRGB out(layers[0]->width, layers[0]->height);
    for (size_t g = 0; g < layers.size(); ++g) {
        const glm::vec3 w = g < weights.size() ? weights[g] : glm::vec3(1.0f);
        const std::vector<glm::vec3>& in = layers[g]->pixels;
        for (size_t p = 0; p < out.pixels.size(); ++p) out.pixels[p] += w * in[p];
    }
    return out;
}

util::ImageRGB mixGroupLayers(const std::vector<util::ImageRGB>& layers,
                              const std::vector<glm::vec3>& weights) {
    std::vector<const util::ImageRGB*> pointers;
    for (const util::ImageRGB& layer : layers) pointers.push_back(&layer);
    return mixGroupLayers(pointers, weights);
}

uint64_t lightGroupLayerBytes(size_t groups, int width, int height) {
    return uint64_t(groups) * uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0)) * 12u;
}

} // namespace wavelit::render
