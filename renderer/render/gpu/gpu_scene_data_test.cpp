// Packing the scene for the shader, without a device: material order and the default material
// that bvh.cpp's unknown-material index points at, BRDF codes, environment texel order, camera
// axes and the per-pass seed of docs/estimator.md.
#include "render/gpu/gpu_scene_data.h"

#include "render/testing/cpu_analytic_scenes.h"

#include <gtest/gtest.h>

namespace wavelit::render {
namespace {

TEST(GpuSceneData, PacksMaterialsWithTrailingDefault) {
    scene::Material gold;
    gold.id = 1;
    gold.brdf = "ggx";
    gold.baseColor = glm::vec3(1.0f, 0.5f, 0.25f);
    gold.roughness = 0.3f;
    gold.emission = glm::vec3(2.0f);
    auto scene = makeFurnaceScene(gold, glm::vec3(1.0f), 8, 4);
    auto bvh = scene::buildBvh(*scene);
    RenderOptions o;
    o.width = 40;
    o.height = 20;
    auto d = packGpuScene(*scene, bvh, o);
    ASSERT_TRUE(d.ok()) << d.error().message();
    ASSERT_EQ(d->materials.size(), 2u);
    EXPECT_EQ(d->materials[0].baseColorRoughness[1], 0.5f);
    EXPECT_EQ(d->materials[0].baseColorRoughness[3], 0.3f);
    EXPECT_EQ(d->materials[0].emissionType[0], 2.0f);
    EXPECT_EQ(d->materials[0].emissionType[3], float(gpuBrdfType(*plugins::findBrdf("ggx"))));
    scene::Material fallback;
    EXPECT_EQ(d->materials[1].baseColorRoughness[0], fallback.baseColor.r);
    EXPECT_EQ(d->materials[1].emissionType[3], float(gpuBrdfType(*plugins::findBrdf("lambert"))));
    // The kernel carries the twins of these two plugins only (the default material's included).
    EXPECT_EQ(d->brdfPlugins, (BrdfPluginSet(1) << gpuBrdfType(*plugins::findBrdf("ggx"))) |
                                  (BrdfPluginSet(1) << gpuBrdfType(*plugins::findBrdf("lambert"))));
    EXPECT_EQ(d->params.envSize[2], 2u);
    EXPECT_EQ(d->params.size[0], 40u);
    EXPECT_EQ(d->params.size[1], 20u);
    EXPECT_EQ(d->params.size[3], uint32_t(bvh.triangles.size()));
    EXPECT_FLOAT_EQ(d->params.camRight[3], 2.0f); // aspect
    // Camera at (0, 0, 4) looking at the origin: forward -Z, right +X, up +Y.
    EXPECT_FLOAT_EQ(d->params.camForward[2], -1.0f);
    EXPECT_FLOAT_EQ(d->params.camRight[0], 1.0f);
    EXPECT_FLOAT_EQ(d->params.camUp[1], 1.0f);
    EXPECT_TRUE(d->envTexels.empty());
    EXPECT_EQ(d->params.envSize[0], 0u);
}

TEST(GpuSceneData, PacksEnvironmentRowMajorTopRowFirst) {
    scene::Material m;
    auto scene = makeFurnaceScene(m, glm::vec3(1.0f), 8, 4);
    auto env = std::make_shared<util::ImageRGB>(3, 2);
    env->at(2, 0) = glm::vec3(1, 2, 3);
    env->at(0, 1) = glm::vec3(4, 5, 6);
    scene->lighting.environment.image = env;
    scene->lighting.environment.rotationDeg = 90.0f;
    auto d = packGpuScene(*scene, scene::buildBvh(*scene), RenderOptions{});
    ASSERT_TRUE(d.ok());
    ASSERT_EQ(d->envTexels.size(), 18u);
    EXPECT_EQ(d->envTexels[6], 1.0f);
    EXPECT_EQ(d->envTexels[8], 3.0f);
    EXPECT_EQ(d->envTexels[9], 4.0f);
    EXPECT_EQ(d->params.envSize[0], 3u);
    EXPECT_EQ(d->params.envSize[1], 2u);
    EXPECT_NEAR(d->params.envRotation[0], 0.0f, 1e-6f); // cos 90
    EXPECT_NEAR(d->params.envRotation[1], 1.0f, 1e-6f); // sin 90
}

TEST(GpuSceneData, UnknownBrdfNamesTheMaterial) {
    scene::Material m;
    m.name = "velvet";
    m.brdf = "sheen";
    auto scene = makeFurnaceScene(m, glm::vec3(1.0f), 8, 4);
    auto d = packGpuScene(*scene, scene::buildBvh(*scene), RenderOptions{});
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error().kind, util::ErrorKind::Unsupported);
    EXPECT_NE(d.error().message().find("velvet"), std::string::npos);
    EXPECT_EQ(d.error().where, "/materials/0/brdf");
}

} // namespace
} // namespace wavelit::render
