// `measured`: an isotropic measured BRDF looked up in a MERL-layout table (brdf_table.h)
// that the material's brdfFile names (a path relative to the scene file, loaded with the meshes:
// scene_io's loadAssets). f = baseColor × table(wo, wi): baseColor is a tint, 1 reproduces the
// file. Without a table (a material not yet loaded) f is 0.
//
// Sampling: cosine-weighted (pdf = cosθi/π), so every direction the table can reflect into is
// reachable whatever the data; the lobe is declared about the normal with the whole hemisphere
// as its width, which the product samplers then resolve from the tabulated f itself
// (docs/brdfs.md: what this costs on glossy data). GLSL twin: measured.glsl, which reads the
// scene's tables from a storage buffer (render/gpu/gpu_brdf_tables.h) and finds a material's
// table by the offset the GPU material carries in its roughness slot.
#include "plugins/brdf.h"
#include "plugins/brdf_table.h"

#include "util/hemisphere_sampling.h"

#include <array>
#include <numbers>

namespace wavelit::plugins {
namespace {

constexpr std::array<BrdfParameterInfo, 2> kParameters{{
    {"baseColor", "Tint", BrdfParameterType::Color, 0.0f, 1.0f, glm::vec3(1.0f),
     "Multiplies the measured reflectance; 1 reproduces the file"},
    {"brdfFile", "Measured BRDF file", BrdfParameterType::File, 0.0f, 0.0f, glm::vec3(0.0f),
     "Isotropic BRDF in the MERL binary layout (.binary), relative to the scene file"},
}};

class Measured final : public Brdf {
public:
    const char* name() const override { return "measured"; }
    std::span<const BrdfParameterInfo> parameters() const override { return kParameters; }
    BrdfLobeAxis lobeAxis() const override { return BrdfLobeAxis::Normal; }
    // The lobe about the normal over the whole sphere (cosine sampling reaches all of it); its
    // half-width is the table's own at normal view (BrdfTable::halfWidthAtNormalView): a glossy
    // table then gets the product sampler's lobe refinement at its lobe's scale instead of at the
    // hemisphere's (docs/brdfs.md "Lobe-width hints"). π/2 without a table.
    BrdfLobeWidth lobeWidth(const BrdfParams& p) const override {
        return {p.table ? p.table->halfWidthAtNormalView : 0.5 * std::numbers::pi, 3.2};
    }
    BrdfGpuTwin gpuTwin() const override {
        return {"measured.glsl", "measuredSample", "measuredEval", "measuredPdf"};
    }

    glm::vec3 eval(const BrdfParams& p, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (!p.table || wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        return p.baseColor * p.table->eval(wo, wi);
    }

    BrdfSample sample(const BrdfParams& p, const glm::vec3& wo, float u1, float u2) const override {
        BrdfSample s;
        if (wo.z <= 0.0f) return s;
        s.wi = util::sampleCosineHemisphere(glm::vec2(u1, u2));
        s.pdf = util::cosineHemispherePdf(s.wi);
        if (s.pdf <= 0.0f) return s; // the disk's rim maps to the horizon: invalid
        s.f = eval(p, wo, s.wi);
        s.valid = true;
        return s;
    }

    float pdf(const BrdfParams&, const glm::vec3& wo, const glm::vec3& wi) const override {
        if (wo.z <= 0.0f) return 0.0f;
        return util::cosineHemispherePdf(wi);
    }

    std::optional<glm::vec2> invert(const BrdfParams&, const glm::vec3& wo,
                                    const glm::vec3& wi) const override {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return std::nullopt;
        return util::invertCosineHemisphere(wi);
    }
};

} // namespace

const Brdf& measuredBrdf() {
    static const Measured kInstance;
    return kInstance;
}

} // namespace wavelit::plugins
