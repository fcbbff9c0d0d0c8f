// The CPU reference tracer with every direction sampler (issue 6; RenderOptions::sampler): on a
// GGX sphere (radius 0.2, roughness 0.5) under the bundled studio environment, each sampler's mean image agrees
// with the bsdf sampler's high-spp mean within 4 standard errors per 8x8 block. The standard
// error of a block mean comes from the spread of its per-pass means (one sample per pixel per
// pass), for the sampler under test and the reference together. A biased pdf (one that differs
// from what is drawn) or an MIS weight using the wrong sampler's pdf shows up as a block offset.
#include "render/reference/cpu_path_tracer.h"

#include "render/testing/block_statistics.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/sampling/direction_sampler.h"
#include "render/testing/sampler_test_envs.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

constexpr int kSize = 32;
constexpr int kBlock = 8;
constexpr int kBlocks = (kSize / kBlock) * (kSize / kBlock);
constexpr int kReferencePasses = 2048;
// Passes per sampler: the hemisphere samplers rarely hit the glossy lobe (a heavy tail that a
// short run's spread underestimates), so they get more of their cheap passes; cosine most, as at
// the silhouette (grazing view) GGX's f cos / (cos / pi) = pi f grows toward the horizon. `bsdf`
// too: its first 32 passes are the reference's own first 32, but they still rarely reach the
// studio's small lamps (32 passes: |z| = 5.5 in one block; 768: < 2).
int passesFor(SamplerKind kind) {
    if (kind == SamplerKind::Cosine)
        return 4096;
    return kind == SamplerKind::Uniform || kind == SamplerKind::Bsdf ? 768 : 32;
}
constexpr double kSigmas = 4.0;

std::shared_ptr<const scene::Scene> studioSphere() {
    static const std::shared_ptr<const scene::Scene> scene = [] {
        scene::Material ggx;
        ggx.name = "glossy";
        ggx.brdf = "ggx";
        ggx.baseColor = glm::vec3(0.9f, 0.8f, 0.7f);
        // r = 0.5 and the env at 64 x 32: the studio's small bright lamps are what make short
        // runs heavy-tailed (a 4-sigma test on an empirical spread needs a light tail).
        ggx.roughness = 0.5f;
        auto s = makeFurnaceScene(ggx, glm::vec3(1.0f), 64, 32);
        s->objects[0].transform.scale = glm::vec3(0.2f);
        s->camera.position = glm::vec3(0.0f, 0.0f, 0.8f); // the furnace framing, scaled by 0.2
        auto env = loadDownsampledEnvironment(
            std::string(WAVELIT_RESOURCE_DIR) + "/envmaps/studio.exr", 64);
        EXPECT_TRUE(env.ok());
        if (env.ok()) {
            s->lighting.environment = *env;
            s->lighting.environment.rotationDeg = 30.0f;
        }
        return std::shared_ptr<const scene::Scene>(s);
    }();
    return scene;
}

// Per 8x8 block: the mean over passes of the block's per-pass mean, and its standard error.
BlockStatistics render(SamplerKind kind, int passes) {
    auto scene = studioSphere();
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    RenderOptions o;
    o.width = o.height = kSize;
    o.bounces = 1;
    o.seed = 23;
    o.device = DeviceChoice::Cpu;
    o.sampler = kind;
    auto tracer = CpuPathTracer::create(scene, bvh, o, 1);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error().message());
    BlockStatistics b(kBlocks);
    if (!tracer.ok())
        return b;
    for (int pass = 0; pass < passes; ++pass) {
        std::vector<double> block(kBlocks, 0.0);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec3 v = (*tracer)->samplePixel(x, y, pass);
                EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
                block[size_t((y / kBlock) * (kSize / kBlock) + x / kBlock)] +=
                    double(util::luminance(v)) / (kBlock * kBlock);
            }
        b.addPass(block);
    }
    return b;
}

TEST(CpuPathTracerSamplers, EverySamplerMatchesTheBsdfReferencePerBlock) {
    const BlockStatistics ref = render(SamplerKind::Bsdf, kReferencePasses);
    for (SamplerKind kind : allSamplerKinds()) {
        const BlockStatistics s = render(kind, passesFor(kind));
        double worst = 0.0;
        for (size_t i = 0; i < kBlocks; ++i) {
            const double sigma = combinedSigma(s, ref, i);
            const double z = std::abs(s.mean(i) - ref.mean(i)) / std::max(sigma, 1e-12);
            worst = std::max(worst, z);
            EXPECT_LE(std::abs(s.mean(i) - ref.mean(i)), kSigmas * sigma + 1e-6 * ref.mean(i))
                << samplerKindName(kind) << " block " << i << ": " << s.mean(i) << " vs "
                << ref.mean(i) << " (sigma " << sigma << ")";
        }
        std::printf("[cpu sampler] %-8s worst block |z| = %.2f\n", samplerKindName(kind), worst);
    }
}

TEST(CpuPathTracerSamplers, ReportsTheSamplerTablesForNonBsdfKinds) {
    auto scene = studioSphere();
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    RenderOptions o;
    o.width = o.height = 8;
    o.sampler = SamplerKind::Wavelet;
    auto tracer = CpuPathTracer::create(scene, bvh, o, 1);
    ASSERT_TRUE(tracer.ok());
    // Only the material an object uses gets tables (the default material is unused here).
    EXPECT_NE((*tracer)->samplerReport().find("glossy"), std::string::npos)
        << (*tracer)->samplerReport();
    o.sampler = SamplerKind::Bsdf;
    auto bsdf = CpuPathTracer::create(scene, bvh, o, 1);
    ASSERT_TRUE(bsdf.ok());
    EXPECT_TRUE((*bsdf)->samplerReport().empty());
}

} // namespace
} // namespace wavelit::render
