// Analytic lights on the Vulkan path tracer (shaders/common/lights.glsl) against their CPU twins
// (light_sampler.cpp, light_set.cpp, cpu_path_tracer.cpp's next-event estimation): the same
// estimator and random draws give the same image pixel by pixel, the packed light constants equal
// LightSampler's, and a scene change uploads the new lights. Scene and comparison:
// gpu_lights_test_support.h.
#include "render/gpu/gpu_lights_test_support.h"

#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_scene_data.h"
#include "render/lights/light_sampler.h"
#include "render/session/integrator_factory.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

namespace wavelit::render {
namespace {

using namespace gpu_lights_test;

TEST(GpuLights, PackedConstantsEqualTheCpuLightSampler) {
    // The GPU reads LightSampler's derived constants from packGpuLight: same emission per type.
    for (auto type : {scene::LightType::Point, scene::LightType::Sphere, scene::LightType::Rect,
                      scene::LightType::Spot, scene::LightType::Sun}) {
        scene::Light l = makeLight(type);
        LightSampler cpu(l);
        GpuLight g = packGpuLight(l);
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(g.emissionArea[c], cpu.emission()[c]) << int(type);
        EXPECT_EQ(g.sun[2] != 0.0f, cpu.isDelta()) << int(type);
    }
    // The scene packing carries the lights in order, their count and LightSet's 1/n.
    auto scene = makeLightScene();
    scene->lighting.lights = {makeLight(scene::LightType::Rect), makeLight(scene::LightType::Sun),
                              makeLight(scene::LightType::Point)};
    auto packedScene = packGpuScene(*scene, scene::buildBvh(*scene), gpuOptions(1, 8));
    ASSERT_TRUE(packedScene.ok());
    ASSERT_EQ(packedScene->lights.size(), 3u);
    EXPECT_EQ(packedScene->params.envSize[3], 3u);
    EXPECT_EQ(packedScene->params.lightInfo[0], 1.0f / 3.0f);
    EXPECT_EQ(uint32_t(packedScene->lights[1].positionType[3]), kGpuLightSun);
    scene::Light zero = makeLight(scene::LightType::Sphere);
    zero.radius = 0.0f; // a zero-radius sphere is a point light, as LightSampler makes it
    EXPECT_EQ(uint32_t(packGpuLight(zero).positionType[3]), kGpuLightPoint);
}

TEST(GpuLights, EachLightTypeMatchesTheCpuTracerWithTheSameSeed) {
    struct Case {
        const char* name;
        std::vector<scene::Light> lights;
    };
    scene::Light deltaSun = makeLight(scene::LightType::Sun);
    deltaSun.angularDiameterDeg = 0.0f;
    std::vector<Case> cases = {
        {"point", {makeLight(scene::LightType::Point)}},
        {"sphere", {makeLight(scene::LightType::Sphere)}},
        {"rect", {makeLight(scene::LightType::Rect)}},
        {"spot", {makeLight(scene::LightType::Spot)}},
        {"sun", {makeLight(scene::LightType::Sun)}},
        {"delta sun", {deltaSun}},
        {"all five",
         {makeLight(scene::LightType::Point), makeLight(scene::LightType::Sphere),
          makeLight(scene::LightType::Rect), makeLight(scene::LightType::Spot),
          makeLight(scene::LightType::Sun)}},
    };
    for (const Case& c : cases) {
        auto scene = makeLightScene();
        scene->lighting.lights = c.lights;
        Agreement a = compareWithCpu(scene, 3, 32, 4);
        std::printf("[ gpu lights ] %-9s: %.2f%% pixels match, mean gpu %.5f cpu %.5f\n", c.name,
                    100.0 * a.matching, a.gpuMean, a.cpuMean);
        EXPECT_TRUE(a.finite) << c.name;
        EXPECT_GE(a.matching, kMinMatching) << c.name;
        EXPECT_GT(a.cpuMean, 0.0) << c.name;
        EXPECT_NEAR(a.gpuMean, a.cpuMean, kMeanTolerance * a.cpuMean) << c.name;
        EXPECT_EQ(a.validationMessages, 0) << c.name;
    }
}

TEST(GpuLights, HardCasesStayFiniteAndMatchTheCpu) {
    // Lights lying on the plane, a sphere light cut by it, a 0.53° sun 10^6× the sky on a
    // near-mirror GGX sphere: no NaN/Inf, and the same image as the CPU tracer.
    scene::Light onPlane = makeLight(scene::LightType::Point);
    onPlane.position = glm::vec3(1.0f, 0.0f, 0.5f);
    scene::Light rectOnPlane = makeLight(scene::LightType::Rect);
    rectOnPlane.position = glm::vec3(-1.0f, 0.0f, 0.0f);
    rectOnPlane.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    scene::Light cut = makeLight(scene::LightType::Sphere);
    cut.position = glm::vec3(-1.0f, 0.1f, 1.0f);
    scene::Light sun = makeLight(scene::LightType::Sun);
    sun.angularDiameterDeg = 0.53f;
    sun.intensity = 5e4f; // the sky is 0.05
    auto scene = makeLightScene();
    scene->materials[1].roughness = 0.02f;
    scene->lighting.lights = {onPlane, rectOnPlane, cut, sun};
    Agreement a = compareWithCpu(scene, 3, 32, 4);
    std::printf("[ gpu lights ] hard     : %.2f%% pixels match, mean gpu %.5f cpu %.5f\n",
                100.0 * a.matching, a.gpuMean, a.cpuMean);
    EXPECT_TRUE(a.finite);
    EXPECT_GE(a.matching, kMinMatching);
    EXPECT_NEAR(a.gpuMean, a.cpuMean, kMeanTolerance * a.cpuMean);
    EXPECT_EQ(a.validationMessages, 0);
}

TEST(GpuLights, SetSceneUploadsTheNewLights) {
    // A tracer created without lights, then given a scene with a sphere light (and back): the
    // light buffer, count and selection probability follow the scene.
    auto dark = makeLightScene();
    auto lit = makeLightScene();
    lit->lighting.lights = {makeLight(scene::LightType::Sphere)};
    RenderOptions options = gpuOptions(2, 16);
    auto darkBvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*dark));
    auto litBvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*lit));
    auto gpu = createGpuPathTracer(dark, darkBvh, options);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    const double darkMean = meanLuminance(render(**gpu, 2));
    ASSERT_TRUE((*gpu)->setScene(lit, litBvh).ok());
    util::ImageRGB g = render(**gpu, 2);
    auto cpu = createCpuPathTracer(lit, litBvh, options);
    ASSERT_TRUE(cpu.ok());
    util::ImageRGB c = render(**cpu, 2);
    EXPECT_GT(meanLuminance(g), 2.0 * darkMean);
    EXPECT_NEAR(meanLuminance(g), meanLuminance(c), kMeanTolerance * meanLuminance(c));
    ASSERT_TRUE((*gpu)->setScene(dark, darkBvh).ok());
    EXPECT_NEAR(meanLuminance(render(**gpu, 2)), darkMean, 1e-6 * darkMean + 1e-9);
    EXPECT_EQ((*gpu)->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::render
