// `glossy`: GGX reflection without Fresnel, as Blender's Glossy BSDF (GGX distribution), which
// many imported scenes use: f = baseColor · D(h) G2(wo, wi) / (4 cosθo cosθi), the colour the
// same at every angle. D, G2, alpha = max(r², 1e-4) and visible-normal sampling are ggx's
// (ggx_microfacet.h); only the reflectance differs. Single scattering: albedo ≤ baseColor.
// GLSL twin: glossy.glsl.
#include "plugins/brdf.h"
#include "plugins/ggx_microfacet.h"

#include <array>

namespace wavelit::plugins {
namespace {

using namespace ggx_detail;

constexpr std::array<BrdfParameterInfo, 2> kParameters{{
    {"baseColor", "Colour", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(0.8f),
     "Reflectance at every angle (no Fresnel rise), as Blender's Glossy BSDF colour"},
    {"roughness", "Roughness", BrdfParameterType::Float, 0.0f, 1.0f, glm::vec3(0.5f),
     "Microfacet roughness r; GGX alpha = r^2 (Blender's Roughness)"},
}};

class Glossy final : public GgxLobe {
public:
    const char* name() const override { return "glossy"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfGpuTwin gpuTwin() const override {
        return {"glossy.glsl", "glossySample", "glossyEval", "glossyPdf"};
    }
    glm::vec3 reflectance(const BrdfParams& p, float) const override { return p.baseColor; }
    void evalBatch(const BrdfParams& p, const glm::vec3& wo, const BrdfDirections& wi,
                   const BrdfValues& out) const override {
        const glm::vec3 c = p.baseColor;
        evalLobeBatch(p, wo, wi, out, [c](float, float& r, float& g, float& b) {
            r = c.x;
            g = c.y;
            b = c.z;
        });
    }
};

} // namespace

const Brdf& glossyBrdf() {
    static const Glossy kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
