// The GPU light tests' scene, lights and CPU comparison (see gpu_lights_test_support.h). It holds
// no tests: the *_test.cpp name puts it in the test executable, where it may use render/testing/.
#include "render/gpu/gpu_lights_test_support.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_path_tracer_test_support.h"
#include "render/session/integrator_factory.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::render::gpu_lights_test {

RenderOptions gpuOptions(int bounces, int size) {
    RenderOptions o = gpu_tracer_test::testOptions(bounces, size, size);
    o.seed = 11; // the light tests' images were measured with this seed
    return o;
}

// A Lambert plane y = 0 and a GGX sphere of radius 0.6 resting on it, a dim constant sky.
std::shared_ptr<scene::Scene> makeLightScene() {
    auto s = std::make_shared<scene::Scene>();
    s->camera.position = glm::vec3(0.0f, 2.5f, 3.5f);
    s->camera.target = glm::vec3(0.0f, 0.4f, 0.0f);
    s->camera.verticalFovDeg = 45.0f;
    scene::Material plane;
    plane.id = 1;
    plane.brdf = "lambert";
    plane.baseColor = glm::vec3(kAlbedo, 0.5f, 0.4f);
    scene::Material glossy;
    glossy.id = 2;
    glossy.brdf = "ggx";
    glossy.baseColor = glm::vec3(0.9f, 0.7f, 0.4f);
    glossy.roughness = 0.3f;
    s->materials = {plane, glossy};
    scene::Object ground;
    ground.id = 3;
    ground.materialId = 1;
    ground.mesh = std::make_shared<scene::TriangleMesh>(makeGroundQuad(10.0f));
    s->objects.push_back(ground);
    scene::Object ball;
    ball.id = 4;
    ball.materialId = 2;
    ball.mesh = std::make_shared<scene::TriangleMesh>(makeUvSphere(32, 16));
    ball.transform.translation = glm::vec3(0.0f, 0.6f, 0.0f);
    ball.transform.scale = glm::vec3(0.6f);
    s->objects.push_back(ball);
    s->lighting.environment.intensity = 0.05f;
    return s;
}

util::ImageRGB render(Integrator& integrator, int passes) {
    for (int i = 0; i < passes; ++i) {
        auto status = integrator.renderPass();
        EXPECT_TRUE(status.ok()) << status.error().message();
    }
    auto img = integrator.image();
    EXPECT_TRUE(img.ok());
    return img ? *img : util::ImageRGB();
}

double meanLuminance(const util::ImageRGB& img) {
    double sum = 0.0;
    for (const auto& p : img.pixels)
        sum += util::luminance(p);
    return sum / double(img.pixels.size());
}

bool allFinite(const util::ImageRGB& img) {
    for (const auto& p : img.pixels)
        if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b))
            return false;
    return true;
}

Agreement compareWithCpu(const std::shared_ptr<scene::Scene>& scene, int bounces, int size,
                         int passes) {
    Agreement a;
    RenderOptions options = gpuOptions(bounces, size);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto gpu = createGpuPathTracer(scene, bvh, options);
    EXPECT_TRUE(gpu.ok()) << (gpu.ok() ? "" : gpu.error().message());
    auto cpu = createCpuPathTracer(scene, bvh, options);
    EXPECT_TRUE(cpu.ok()) << (cpu.ok() ? "" : cpu.error().message());
    if (!gpu || !cpu)
        return a;
    util::ImageRGB g = render(**gpu, passes), c = render(**cpu, passes);
    int matching = 0;
    for (size_t i = 0; i < g.pixels.size(); ++i) {
        glm::vec3 d = glm::abs(g.pixels[i] - c.pixels[i]);
        float scale = std::max(1e-3f, util::luminance(c.pixels[i]));
        if (std::max(d.r, std::max(d.g, d.b)) <= kPixelTolerance * scale + 1e-5f)
            ++matching;
    }
    a.matching = double(matching) / double(g.pixels.size());
    a.gpuMean = meanLuminance(g);
    a.cpuMean = meanLuminance(c);
    a.validationMessages = (*gpu)->validationMessageCount();
    a.finite = allFinite(g);
    return a;
}

scene::Light makeLight(scene::LightType type) {
    scene::Light l;
    l.type = type;
    l.position = glm::vec3(1.2f, 2.5f, 1.0f);
    l.color = glm::vec3(1.0f, 0.9f, 0.8f);
    l.intensity = 120.0f;
    switch (type) {
    case scene::LightType::Point:
        break;
    case scene::LightType::Sphere:
        l.radius = 0.3f;
        break;
    case scene::LightType::Rect:
        l.position = glm::vec3(0.5f, 2.0f, 0.8f);
        l.direction = glm::vec3(-0.2f, -1.0f, -0.3f);
        l.size = glm::vec2(1.2f, 0.7f);
        break;
    case scene::LightType::Spot:
        l.direction = glm::normalize(glm::vec3(0.0f, 0.4f, 0.0f) - l.position);
        l.coneInnerDeg = 15.0f;
        l.coneOuterDeg = 30.0f;
        break;
    case scene::LightType::Sun:
        l.direction = glm::vec3(-0.4f, -1.0f, -0.3f);
        l.intensity = 3.0f;
        l.angularDiameterDeg = 5.0f; // wide enough that BSDF-sampled rays find it too
        break;
    }
    return l;
}

} // namespace wavelit::render::gpu_lights_test
