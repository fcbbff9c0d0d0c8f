// LightMix light groups (docs/lightmix.md): which radiance layer each emitter's contributions go
// to. By default one layer per analytic light (named after the light), one `environment` and,
// when some object's material emits, one `emission`; a light's `group` property puts several
// lights into one layer. Radiance is linear in each emitter's, so every contribution of the
// estimator (light NEE, a BSDF-sampled ray hitting a light, env NEE or escape, emission) belongs
// to exactly one layer and the beauty is the sum of the layers (docs/estimator.md "Light groups").
// Pure functions of the scene; no render state.
#pragma once

#include "scene/scene.h"
#include "util/image.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace wavelit::render {

inline constexpr const char* kEnvironmentGroup = "environment";
inline constexpr const char* kEmissionGroup = "emission";

struct LightGroups {
    std::vector<std::string> names; // layer order: lights' groups by first appearance, then
                                    // `environment`, then `emission` (when present)
    std::vector<int> groupOfLight;  // per Scene::lighting.lights index
    int environmentGroup = -1;      // always present: the environment (possibly black)
    int emissionGroup = -1;         // -1: no object's material emits
    size_t size() const { return names.size(); }
};

// The layer name of one light: its group, else its name, else "light-<id>". A light whose group
// is `environment` or `emission` shares that layer.
std::string lightGroupName(const scene::Light& light);

LightGroups lightGroupsOf(const scene::Scene& scene);

// Σ weights[g] × layers[g] (per channel), the LightMix recombination: with every weight 1 it is
// the beauty to float rounding; a missing weight (weights shorter than layers) counts as 1. The
// layers must share one size; no layers: an empty image.
util::ImageRGB mixGroupLayers(const std::vector<util::ImageRGB>& layers,
                              const std::vector<glm::vec3>& weights);
// The same over layers held elsewhere (no copies: the editor's remix, `wavelit-cli mix`).
util::ImageRGB mixGroupLayers(const std::vector<const util::ImageRGB*>& layers,
                              const std::vector<glm::vec3>& weights);

// Bytes of float RGB layers (12 per group and pixel): what the Vulkan tracer allocates; the CPU
// reference sums in double (24).
uint64_t lightGroupLayerBytes(size_t groups, int width, int height);

} // namespace wavelit::render
