// Issue 6 acceptance, "unbiased": every direction sampler on the Vulkan tracer, on a glossy GGX
// sphere above a Lambert ground under (i) a soft environment (the bundled studio, downsampled)
// and (ii) a sky with a one-texel sun 10^6 x the sky's mean, at roughness 0.02 / 0.2 / 1.0: the
// Vulkan mean image matches a high-spp CPU reference (the CPU tracer with `mis`, an independent
// implementation of the same estimator) per 16 x 16 block: none outside 4 standard errors, and
// the fraction within 3 is printed. The standard error of a block mean comes from the spread of
// its per-pass means (one sample per pixel per pass) of both renders. A pdf that differs from what
// is drawn, a product pyramid decoded wrongly, or MIS weights with the wrong pdf show as offsets.
// Also: zero validation messages and no NaN/Inf in any pass.
#include "render/testing/block_statistics.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/reference/cpu_path_tracer.h"
#include "render/sampling/direction_sampler.h"
#include "render/sampling/product/env_product_tables.h"
#include "render/sampling/sampler_environment.h"
#include "render/session/integrator_factory.h"
#include "render/testing/sampler_test_envs.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

constexpr int kSize = 48;
constexpr int kBlock = 16;
constexpr int kBlocksPerSide = kSize / kBlock;
constexpr int kBlocks = kBlocksPerSide * kBlocksPerSide;
constexpr int kReferencePasses = 512;
constexpr double kFailSigmas = 4.0;

// WideSun: the same sky with a 30-degree sun 10^6 x its mean (effective solid angle ~0.2 sr),
// where a ggx r = 0.35 lobe (0.19 sr) keeps `wavelet`'s product under the two-sided extents rule:
// under the one-texel sun every lobe the 64-wide map resolves is wider than the sun (EnvMis)
// and r = 0.02 / 0.2 are narrower than its texels (BsdfLobe), so only this case renders the
// product under a concentrated light.
enum class Lighting { Soft, Sun, WideSun };

// Which (sampler, lighting, roughness) a finite run can judge. A one-technique sampler is
// unbiased everywhere but, where its density misses a bright part of the integrand, its mean
// converges through rare huge weights (a heavy tail: the spread of a short run underestimates its
// error). Measured with 128-512 passes: uniform and cosine reach the r = 0.2 lobe under the
// studio's small lamps 1e-3 of the time (|z| 4.9 / 12); bsdf finds the one-texel sun through an
// r >= 0.2 lobe too rarely (|z| 34-40); env puts 99.9% of its draws on the sun and the sky's share
// of a lobe gets a handful (|z| 5-280). Under the sun even r = 0.02 is not judgeable for bsdf
// since the `mis` reference does env NEE (issue 20): the sun's glow in the GGX tail around its
// reflection (directions where the BSDF pdf is < 1e-3) adds 0.00102 to block 1's 0.3867, which NEE
// resolves and BSDF sampling essentially never reaches (CPU bsdf, 4096 passes, two seeds:
// 0.38567 +- 0.00004, vs mis 0.38664 +- 0.00005; |z| 6.2 at 128 passes against a reference whose
// error bar no longer hides it). Those cases are judged instead by the twin test
// (GpuPathTracer.MatchesCpuReferenceWithTheSameRandomStreams: same numbers, same image as the CPU
// sampler, whose distribution and pdf pass chi-square in direction_sampler_test.cpp).
bool judged(SamplerKind kind, Lighting lighting, float roughness) {
    switch (kind) {
    case SamplerKind::Mis:
    case SamplerKind::Wavelet:
    case SamplerKind::Oracle:
        return true;
    case SamplerKind::Bsdf:
        return lighting == Lighting::Soft;
    case SamplerKind::Env:
        return lighting == Lighting::Soft && roughness > 0.5f;
    case SamplerKind::Uniform:
    case SamplerKind::Cosine:
        // Under the one-texel sun, block 0 gets nearly all its light from paths that hemisphere
        // sampling reaches about once per 65536 samples (a hit is worth ~7.6 of the block's 4.34):
        // on the CPU, 256 passes, cosine read 0.2513 +- 0.0001 (no hit), uniform 1.74 +- 1.48
        // (one), mis 4.336 +- 0.034. A run that short passes or fails by luck, so only the soft
        // environment judges them.
        return roughness > 0.5f && lighting == Lighting::Soft;
    }
    return false;
}
int passesFor(SamplerKind kind) {
    if (const char* e = std::getenv("WAVELIT_TEST_PASSES")) return std::atoi(e);
    // The oracle's small defensive shares (bsdf 0.05, env >= 0.02, as on the CPU) leave it the
    // most skewed weights where its window misses part of the integrand (a mirror lobe's GGX tail
    // over the studio's lamps): 64 passes read block 7 of soft r = 0.02 at |z| 4.4 and 256 at 1.95
    // (same seed), so it gets the uniform sampler's count.
    // bsdf reaches the studio's small lamps through the r = 0.2 lobe rarely: 128 passes (seed 41,
    // Sobol' passes) read block 2 at 0.002418 +- 0.000007 (|z| 14: no lamp found), 2048 passes
    // on the CPU 0.002714 +- 0.000099 against mis 0.002700 +- 0.000011; so it gets 1024.
    if (kind == SamplerKind::Bsdf) return 1024;
    return kind == SamplerKind::Uniform || kind == SamplerKind::Cosine || kind == SamplerKind::Oracle
               ? 256
               : 128;
}

scene::TriangleMesh groundQuad() {
    scene::TriangleMesh m;
    m.positions = {{-3, -1, -3}, {3, -1, -3}, {3, -1, 3}, {-3, -1, 3}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.indices = {0, 2, 1, 0, 3, 2};
    return m;
}

std::shared_ptr<const scene::Scene> makeScene(Lighting lighting, float roughness) {
    scene::Material ggx;
    ggx.name = "glossy";
    ggx.brdf = "ggx";
    ggx.baseColor = glm::vec3(0.9f, 0.8f, 0.7f);
    ggx.roughness = roughness;
    auto s = makeFurnaceScene(ggx, glm::vec3(1.0f), 64, 32);
    s->camera.position = glm::vec3(0.0f, 1.0f, 4.0f);
    s->camera.verticalFovDeg = 45.0f;
    scene::Material ground;
    ground.id = 7;
    ground.name = "ground";
    ground.brdf = "lambert";
    ground.baseColor = glm::vec3(0.5f);
    s->materials.push_back(ground);
    scene::Object floor;
    floor.id = 8;
    floor.name = "floor";
    floor.mesh = std::make_shared<scene::TriangleMesh>(groundQuad());
    floor.materialId = 7;
    s->objects.push_back(floor);
    if (lighting != Lighting::Soft) {
        // The sun's reflection lands on the sphere (up and behind the camera's shoulder).
        s->lighting.environment = makeSunSkyEnvironment(
            64, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e6,
            lighting == Lighting::Sun ? 0.53 : 30.0);
    } else {
        auto env = loadDownsampledEnvironment(
            std::string(WAVELIT_RESOURCE_DIR) + "/envmaps/studio.exr", 64);
        EXPECT_TRUE(env.ok()) << (env.ok() ? "" : env.error().message());
        if (env.ok())
            s->lighting.environment = *env;
    }
    s->lighting.environment.rotationDeg = 30.0f;
    return s;
}

struct BlockStats {
    BlockStatistics blocks{kBlocks};
    int validation = 0;
    bool finite = true;
};

// Renders `passes` passes, reading the image back after each to get per-pass block means.
BlockStats render(const std::shared_ptr<const scene::Scene>& scene, SamplerKind kind,
                  DeviceChoice device, int passes, uint64_t seed) {
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    RenderOptions o;
    o.width = o.height = kSize;
    o.bounces = 2;
    o.seed = seed;
    o.device = device;
    o.sampler = kind;
    o.validation = true;
    auto integrator = device == DeviceChoice::Cpu ? createCpuPathTracer(scene, bvh, o)
                                                  : createGpuPathTracer(scene, bvh, o);
    BlockStats b;
    EXPECT_TRUE(integrator.ok()) << (integrator.ok() ? "" : integrator.error().message());
    if (!integrator.ok())
        return b;
    Integrator& it = **integrator;
    std::vector<double> previous(size_t(kSize) * kSize, 0.0);
    for (int pass = 0; pass < passes; ++pass) {
        EXPECT_TRUE(it.renderPass().ok());
        auto img = it.image();
        EXPECT_TRUE(img.ok());
        if (!img.ok())
            return b;
        std::vector<double> block(kBlocks, 0.0);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                const glm::vec3 v = img->pixels[i];
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                    b.finite = false;
                // This pass's sample: the running sum's increment.
                const double total = double(util::luminance(v)) * (pass + 1);
                block[size_t((y / kBlock) * kBlocksPerSide + x / kBlock)] +=
                    (total - previous[i]) / (kBlock * kBlock);
                previous[i] = total;
            }
        b.blocks.addPass(block);
    }
    b.validation = it.validationMessageCount();
    return b;
}

struct Config {
    Lighting lighting;
    float roughness;
};

class GpuSamplerUnbiased : public ::testing::TestWithParam<Config> {};

TEST_P(GpuSamplerUnbiased, EverySamplerMatchesTheCpuReferencePerBlock) {
    const Config c = GetParam();
    const auto scene = makeScene(c.lighting, c.roughness);
    // Its own seed: the GPU `mis` run must not share the reference's random streams.
    const BlockStats ref = render(scene, SamplerKind::Mis, DeviceChoice::Cpu, kReferencePasses, 4242);
    ASSERT_TRUE(ref.finite);
    if (c.lighting == Lighting::WideSun) {
        const ProductPolicy p = chooseProductPolicy(
            *plugins::findBrdf("ggx"), {scene->materials[0].baseColor, c.roughness},
            SamplerEnvironment::build(scene->lighting.environment));
        ASSERT_EQ(p.mode, ProductMode::Product) << p.reason;
    }
    for (SamplerKind kind : allSamplerKinds()) {
        if (!judged(kind, c.lighting, c.roughness))
            continue;
        const BlockStats s = render(scene, kind, DeviceChoice::Vulkan, passesFor(kind), 41);
        EXPECT_TRUE(s.finite) << samplerKindName(kind);
        EXPECT_EQ(s.validation, 0) << samplerKindName(kind);
        double worst = 0.0;
        int within3 = 0;
        for (size_t i = 0; i < kBlocks; ++i) {
            const double sigma = combinedSigma(s.blocks, ref.blocks, i);
            const double difference = std::abs(s.blocks.mean(i) - ref.blocks.mean(i));
            const double z = difference / std::max(sigma, 1e-9 * ref.blocks.mean(i) + 1e-12);
            worst = std::max(worst, z);
            within3 += z <= 3.0 ? 1 : 0;
            EXPECT_LE(z, kFailSigmas) << samplerKindName(kind) << " block " << i << ": "
                                      << s.blocks.mean(i) << " vs " << ref.blocks.mean(i)
                                      << " (sigma " << sigma << ")";
        }
        std::printf("[gpu unbiased] %s r=%.2f %-8s worst |z| %.2f, %d/%d blocks within 3 SE\n",
                    c.lighting == Lighting::Sun       ? "sun "
                    : c.lighting == Lighting::WideSun ? "wide sun"
                                                      : "soft",
                    c.roughness,
                    samplerKindName(kind), worst, within3, kBlocks);
    }
}

INSTANTIATE_TEST_SUITE_P(GlossySphere, GpuSamplerUnbiased,
                         ::testing::Values(Config{Lighting::Soft, 0.02f}, Config{Lighting::Soft, 0.2f},
                                           Config{Lighting::Soft, 1.0f}, Config{Lighting::Sun, 0.02f},
                                           Config{Lighting::Sun, 0.2f}, Config{Lighting::Sun, 1.0f},
                                           Config{Lighting::WideSun, 0.35f}),
                         [](const ::testing::TestParamInfo<Config>& info) {
                             const Lighting l = info.param.lighting;
                             return std::string(l == Lighting::Sun       ? "Sun"
                                                : l == Lighting::WideSun ? "WideSun"
                                                                         : "Soft") +
                                    "R" + std::to_string(int(info.param.roughness * 100 + 0.5f));
                         });

} // namespace
} // namespace wavelit::render
