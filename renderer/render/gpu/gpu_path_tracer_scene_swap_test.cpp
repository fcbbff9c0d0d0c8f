// The Vulkan path tracer across scene swaps and resets, on the real device (lavapipe in CI) with
// validation on: a reset repeats the image exactly, setScene swaps the data and keeps the
// pipeline, and each edit rebuilds only the sampler tables it invalidates.
#include "render/gpu/gpu_path_tracer_test_support.h"
#include "render/sampling/sampler_tables_cache.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <memory>

namespace wavelit::render {
namespace {

using namespace gpu_tracer_test;

TEST(GpuPathTracer, ResetAccumulationStartsOver) {
    scene::Material mat;
    mat.id = 1;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 16, 8);
    auto gpu = makeGpu(scene, testOptions(2, 16, 16));
    ASSERT_TRUE(gpu);
    util::ImageRGB first = renderPasses(*gpu, 1);
    renderPasses(*gpu, 2);
    gpu->resetAccumulation();
    EXPECT_EQ(gpu->samplesPerPixel(), 0);
    util::ImageRGB again = renderPasses(*gpu, 1);
    // Pass 0 uses the same seed after a reset, so the image repeats exactly.
    for (size_t i = 0; i < first.pixels.size(); ++i)
        ASSERT_EQ(first.pixels[i], again.pixels[i]);
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

TEST(GpuPathTracer, SetSceneSwapsDataAndKeepsThePipeline) {
    scene::Material mat;
    mat.id = 1;
    auto first = makeFurnaceScene(mat, glm::vec3(1.0f), 16, 8);
    auto gpu = makeGpu(first, testOptions(1, 16, 16));
    ASSERT_TRUE(gpu);
    util::ImageRGB before = renderPasses(*gpu, 2);
    const double pipelineSeconds = gpu->timings().pipelineSeconds;
    EXPECT_EQ(before.at(0, 0), glm::vec3(1.0f)); // a corner sees the environment

    // Brighter environment, sphere moved out of view: every pixel is the new environment.
    auto second = makeFurnaceScene(mat, glm::vec3(2.0f), 16, 8);
    second->objects[0].transform.translation = glm::vec3(0.0f, 50.0f, 0.0f);
    auto status =
        gpu->setScene(second, std::make_shared<const scene::Bvh>(scene::buildBvh(*second)));
    ASSERT_TRUE(status.ok()) << status.error().message();
    EXPECT_EQ(gpu->samplesPerPixel(), 0);
    util::ImageRGB after = renderPasses(*gpu, 1);
    for (const auto& p : after.pixels)
        ASSERT_EQ(p, glm::vec3(2.0f));
    EXPECT_EQ(gpu->timings().pipelineSeconds, pipelineSeconds); // not rebuilt

    // A scene the GPU cannot draw is refused and the previous one stays usable.
    scene::Material odd;
    odd.brdf = "toon";
    auto third = makeFurnaceScene(odd, glm::vec3(3.0f), 8, 4);
    EXPECT_FALSE(
        gpu->setScene(third, std::make_shared<const scene::Bvh>(scene::buildBvh(*third))).ok());
    util::ImageRGB still = renderPasses(*gpu, 1);
    EXPECT_EQ(still.at(5, 5), glm::vec3(2.0f));
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

TEST(GpuPathTracer, SetSceneRebuildsOnlyTheSamplerTablesAnEditInvalidates) {
    // architecture.md §5: object move -> BVH only; env rotation -> the env tables turned (every
    // table is env-local: nothing rebuilt, new tables to upload); env intensity -> nothing (the
    // tables are built at intensity 1); env tint -> env side (and the product tables, which hold
    // env factors); material edit -> that material's tables.
    scene::Material mat;
    mat.id = 1;
    mat.brdf = "ggx";
    // Both roughnesses in product mode (the 32 x 16 map's texels are 0.11 rad: r <= 0.33 would be
    // BsdfLobe, lobes of 2-4 texels, r < 0.47, EnvMis), and a bright texel keeps the env's
    // effective solid angle within 16x of the lobes (not EnvMis): a kernel whose scene draws from
    // no product is compiled without the code, and the edit to a product would then recreate the
    // tracer instead.
    mat.roughness = 0.5f;
    auto scene = makeFurnaceScene(mat, glm::vec3(1.0f), 24, 12);
    auto env = gradientEnvironment();
    env->at(5, 3) = glm::vec3(1e4f);
    scene->lighting.environment.image = env;
    RenderOptions options = testOptions(2, 16, 16);
    options.sampler = SamplerKind::Wavelet;
    auto gpu = makeGpu(scene, options);
    ASSERT_TRUE(gpu);
    renderPasses(*gpu, 1);
    const auto tables = gpu->samplerTables();
    ASSERT_TRUE(tables);
    const SamplerTablesRebuilds start = gpu->samplerRebuilds();
    EXPECT_EQ(start.environmentBuilds, 1);
    EXPECT_EQ(start.materialBuilds, 1); // the one material in use

    auto swap = [&](const std::shared_ptr<scene::Scene>& next) {
        auto status = gpu->setScene(next, std::make_shared<const scene::Bvh>(scene::buildBvh(*next)));
        ASSERT_TRUE(status.ok()) << status.error().message();
        renderPasses(*gpu, 1);
    };
    auto moved = std::make_shared<scene::Scene>(*scene);
    moved->objects[0].transform.translation = glm::vec3(0.3f, 0.0f, 0.0f);
    swap(moved);
    EXPECT_EQ(gpu->samplerTables(), tables); // nothing rebuilt, nothing new to hold
    EXPECT_EQ(gpu->samplerRebuilds().environmentBuilds, 1);
    EXPECT_EQ(gpu->samplerRebuilds().materialBuilds, 1);

    auto edited = std::make_shared<scene::Scene>(*moved);
    edited->materials[0].roughness = 0.6f;
    swap(edited);
    EXPECT_EQ(gpu->samplerRebuilds().environmentBuilds, 1);
    EXPECT_EQ(gpu->samplerRebuilds().materialBuilds, 2);

    auto rotated = std::make_shared<scene::Scene>(*edited);
    rotated->lighting.environment.rotationDeg = 45.0f;
    const auto beforeRotation = gpu->samplerTables();
    swap(rotated);
    EXPECT_NE(gpu->samplerTables(), beforeRotation);
    EXPECT_EQ(gpu->samplerRebuilds().environmentBuilds, 1);
    EXPECT_EQ(gpu->samplerRebuilds().environmentRotations, 1);
    EXPECT_EQ(gpu->samplerRebuilds().materialBuilds, 2);

    auto brighter = std::make_shared<scene::Scene>(*rotated);
    brighter->lighting.environment.intensity = 2.0f;
    const auto beforeIntensity = gpu->samplerTables();
    swap(brighter);
    EXPECT_EQ(gpu->samplerTables(), beforeIntensity); // nothing new to upload
    EXPECT_EQ(gpu->samplerRebuilds().environmentBuilds, 1);
    EXPECT_EQ(gpu->samplerRebuilds().materialBuilds, 2);

    auto tinted = std::make_shared<scene::Scene>(*brighter);
    tinted->lighting.environment.tint = glm::vec3(1.0f, 0.5f, 0.25f);
    swap(tinted);
    EXPECT_EQ(gpu->samplerRebuilds().environmentBuilds, 2);
    EXPECT_EQ(gpu->samplerRebuilds().materialBuilds, 3);
    EXPECT_EQ(gpu->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::render
