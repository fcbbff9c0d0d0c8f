// `ggx`: Trowbridge–Reitz microfacet reflection with height-correlated Smith masking–shadowing
// and Schlick's Fresnel (docs/estimator.md "BRDFs"). Parameters: baseColor (F0, the specular
// colour at normal incidence) and roughness r in [0, 1] with alpha = max(r², 1e-4): the floor keeps
// D finite in float for r → 0 (a lobe narrower than 1e-4 is a mirror for every practical scene).
//
// Sampling: visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals",
// JCGT 7(4)), wi = reflect(−wo, h), pdf = D(h) G1(wo) / (4 cosθo). VNDF beats sampling D because
// f·cos/pdf = F G2/G1 ≤ 1 — no weight blows up at grazing views. Single scattering only: energy
// lost between microfacets is not returned, so the albedo is < 1 at high roughness (tests check ≤ 1).
//
// Numerics: 1 − cos²θ is computed as x² + y² of the unit vector, never as 1 − z², because near the
// mirror direction z² rounds to 1 in float while alpha² can be 1.6e-7 (r = 0.02).
// GLSL twin: ggx.glsl.
#include "plugins/brdf.h"
#include "plugins/ggx_microfacet.h"

#include "util/hemisphere_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace wavelit::plugins {
namespace {

using namespace ggx_detail;

constexpr std::array<BrdfParameterInfo, 2> kParameters{{
    {"baseColor", "Specular colour (F0)", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(0.8f),
     "Reflectance at normal incidence (Schlick F0); rises to 1 at grazing angles"},
    {"roughness", "Roughness", BrdfParameterType::Float, 0.0f, 1.0f, glm::vec3(0.5f),
     "Microfacet roughness r; GGX alpha = r^2. 0 is a mirror, 1 is very rough"},
}};

class Ggx final : public GgxLobe {
public:
    const char* name() const override { return "ggx"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfGpuTwin gpuTwin() const override {
        return {"ggx.glsl", "ggxSample", "ggxEval", "ggxPdf"};
    }
    glm::vec3 reflectance(const BrdfParams& p, float cosThetaD) const override {
        return schlick(p.baseColor, cosThetaD);
    }
    void evalBatch(const BrdfParams& p, const glm::vec3& wo, const BrdfDirections& wi,
                   const BrdfValues& out) const override {
        evalLobeBatch(p, wo, wi, out, SchlickBatch{p.baseColor});
    }
};

} // namespace

const Brdf& ggxBrdf() {
    static const Ggx kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
