// Which `wavelet` materials get the larger defensive BSDF share (gpu_sampler_data.h), decided from
// the lobe traits alone: a Lambert lobe is EnvMis under every env since round 5
// (docs/performance.md); mirror lobes and a measured table's lobe build their product per hit; a
// mirror lobe whose cap is under kGpuNarrowLobeCap gets kGpuNarrowLobeMixBsdf, the others the policy's share. The
// variance figures behind the rule are in docs/brdfs.md ("The Vulkan `wavelet` on these plugins").
#include "render/gpu/gpu_sampler_data.h"

#include "plugins/brdf_table.h"
#include "render/sampling/direction_sampler_tables.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_tables_cache.h"
#include "render/testing/sampler_test_envs.h"
#include "util/image.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <memory>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

TEST(GpuSamplerData, ProductLobesBuildTheirProductPerHitWithThePolicysShare) {
    // 256 x 128: env texels of 0.025 rad, so blinn r = 0.2 (half-width 0.08) is sampled by the
    // product, not left to BSDF sampling. Each lobe under a sun (10^4 x the sky) of its own
    // extent, so the two-sided extents rule keeps its product: 13 degrees across (~0.05 sr) for
    // the r = 0.2 lobes (0.02 sr) and the measured table, 80 degrees (~1.5 sr) for ggx r = 0.5
    // (0.77 sr). One sun cannot serve both: a light inside a lobe is left to env sampling.
    auto table = plugins::loadMerlBrdf(std::string(WAVELIT_RESOURCE_DIR) +
                                       "/brdfs/glossy-copper-r05.binary");
    ASSERT_TRUE(table.ok()) << table.error().message();

    struct Expect {
        SamplerMaterial material;
        double mixBsdf;
        double sunDiameterDeg;
    };
    const std::vector<Expect> cases = {
        {{"ggx r=0.2 (cap 0.36)", plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.2f}},
         kWaveletBsdfShare, 13.0},
        {{"ggx r=0.5 (whole sphere)", plugins::findBrdf("ggx"), {glm::vec3(0.9f), 0.5f}},
         kWaveletBsdfShare, 80.0},
        {{"blinn r=0.2 (cap 0.24)", plugins::findBrdf("blinn"), {glm::vec3(0.9f), 0.2f}},
         kGpuNarrowLobeMixBsdf, 13.0},
        {{"measured", plugins::findBrdf("measured"), {glm::vec3(1.0f), 0.5f, 0.0f, *table}},
         kWaveletBsdfShare, 13.0},
    };
    for (const Expect& c : cases) {
        SCOPED_TRACE(c.material.name);
        const scene::Environment env = makeSunSkyEnvironment(
            256, glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f)), 1e4, c.sunDiameterDeg);
        SceneSamplerTables scene;
        scene.samplerIndexOfMaterial = {0};
        scene.tables = DirectionSamplerTables::build(env, {c.material}, SamplerKind::Wavelet);
        auto packed = packGpuSamplers(scene, SamplerKind::Wavelet, 1);
        ASSERT_TRUE(packed.ok()) << packed.error().message();
        const GpuSamplerMaterial& g = packed->materials[0];
        ASSERT_EQ(g.mode, kGpuSamplerProduct) << scene.tables->report();
        EXPECT_FLOAT_EQ(g.mixBsdf, float(c.mixBsdf));
    }
}

// A Lambert lobe is EnvMis under every lit env (round 5), packed as such with no tables of its
// own: under the spiky env, whose light sits in one texel (env sampling follows the integrand),
// and under a soft one (a bright upper half: effective solid angle 3.6 pi sr, wider than the
// cosine's 1.5 pi, where the extents rule alone kept the product), where the product was
// measured not to pay for its pass.
TEST(GpuSamplerData, ALambertLobeIsPackedEnvMisUnderASunAndUnderASoftMap) {
    auto spiky = std::make_shared<util::ImageRGB>(256, 128, glm::vec3(0.5f));
    spiky->at(40, 30) = glm::vec3(1e4f);
    auto soft = std::make_shared<util::ImageRGB>(256, 128, glm::vec3(0.5f));
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 256; ++x)
            soft->at(x, y) = glm::vec3(1.0f);
    for (const auto& image : {spiky, soft}) {
        scene::Environment env;
        env.image = image;
        SceneSamplerTables scene;
        scene.samplerIndexOfMaterial = {0};
        scene.tables = DirectionSamplerTables::build(
            env, {{"lambert", plugins::findBrdf("lambert"), {glm::vec3(0.8f), 1.0f}}},
            SamplerKind::Wavelet);
        EXPECT_FALSE(scene.tables->anyProduct());
        auto packed = packGpuSamplers(scene, SamplerKind::Wavelet, 1);
        ASSERT_TRUE(packed.ok()) << packed.error().message();
        EXPECT_EQ(packed->materials[0].mode, kGpuSamplerEnvMis);
    }
}

} // namespace
} // namespace wavelit::render
