// Analytic lights on the Vulkan path tracer (shaders/common/lights.glsl) against their CPU twins
// (light_sampler.cpp, light_set.cpp, cpu_path_tracer.cpp's next-event estimation): the same
// estimator and random draws give the same image pixel by pixel, a closed form holds on the GPU,
// the packed light constants equal LightSampler's, and the default scene's softbox renders.
// Validation is on everywhere; images are small because lavapipe runs on the test machine's CPU.
#include "render/testing/cpu_analytic_scenes.h"
#include "render/reference/cpu_camera.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/gpu/gpu_scene_data.h"
#include "render/session/integrator_factory.h"
#include "render/lights/light_sampler.h"
#include "render/session/render_session.h"
#include "scene/bvh.h"
#include "scene/scene_io.h"
#include "util/rng.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr uint64_t kPassStride = 0x9E3779B97F4A7C15ULL; // docs/estimator.md "Random numbers"
constexpr float kAlbedo = 0.6f;

// GPU vs CPU with the same seed. Both draw the same numbers in the same order, so a pixel differs
// only where float rounding (LLVM's sin/cos/acos/sqrt vs libm, fused multiply-adds) flips a branch
// — a cone's rim test, Russian roulette, a shadow ray grazing an edge — and the path diverges.
// kPixelTolerance: relative agreement of a non-diverged pixel (rounding through up to 3 bounces is
// ~1e-5; 1e-3 leaves margin and is the threshold of the light-free CPU/GPU test). kMinMatching:
// at most 2% of pixels may hold a diverged path (measured far fewer). kMeanTolerance: a diverged
// path is another unbiased sample, so means differ only by those few paths' noise; 2% bounds it at
// 4 spp with fireflies from the GGX sphere.
constexpr float kPixelTolerance = 1e-3f;
constexpr double kMinMatching = 0.98;
constexpr double kMeanTolerance = 0.02;
// The closed form's tolerance (the brief): a delta light with bounces = 1 has no Monte Carlo
// noise once the camera jitter is replayed, so only float rounding remains.
constexpr double kClosedFormTolerance = 0.01;

RenderOptions gpuOptions(int bounces, int size) {
    RenderOptions o;
    o.width = size;
    o.height = size;
    o.bounces = bounces;
    o.seed = 11;
    o.device = DeviceChoice::Vulkan;
    o.validation = true;
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
    auto mesh = std::make_shared<scene::TriangleMesh>();
    const float h = 10.0f;
    mesh->positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    mesh->indices = {0, 2, 1, 0, 3, 2};
    ground.mesh = mesh;
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

struct Agreement {
    double matching = 0.0; // fraction of pixels within kPixelTolerance
    double gpuMean = 0.0, cpuMean = 0.0;
    int validationMessages = 0;
    bool finite = false;
};

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

TEST(GpuLights, LambertPlaneUnderAPointLightIsTheClosedForm) {
    // Direct lighting only (bounces = 1), black sky: each sample is ρ/π · Φ/(4π d²) · cos θ at
    // the point its camera ray hits, which the test finds by replaying the camera jitter.
    auto s = std::make_shared<scene::Scene>();
    s->camera.position = glm::vec3(0.0f, 3.0f, 3.0f);
    s->camera.target = glm::vec3(0.0f);
    s->camera.verticalFovDeg = 40.0f;
    scene::Material m;
    m.id = 1;
    m.baseColor = glm::vec3(kAlbedo);
    s->materials.push_back(m);
    scene::Object o;
    o.id = 2;
    o.materialId = 1;
    auto mesh = std::make_shared<scene::TriangleMesh>();
    const float h = 20.0f;
    mesh->positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    mesh->indices = {0, 2, 1, 0, 3, 2};
    o.mesh = mesh;
    s->objects.push_back(o);
    s->lighting.environment.intensity = 0.0f;
    scene::Light l;
    l.type = scene::LightType::Point;
    l.position = glm::vec3(0.3f, 2.0f, -0.5f);
    l.intensity = 50.0f;
    s->lighting.lights.push_back(l);

    constexpr int kSize = 32, kPasses = 4;
    RenderOptions options = gpuOptions(1, kSize);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*s));
    auto gpu = createGpuPathTracer(s, bvh, options);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    util::ImageRGB img = render(**gpu, kPasses);
    CpuCamera camera(s->camera, kSize, kSize);
    double maxError = 0.0, sumRendered = 0.0, sumExpected = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            double expected = 0.0;
            for (int pass = 0; pass < kPasses; ++pass) {
                util::Pcg32 rng(options.seed ^ (uint64_t(pass) * kPassStride),
                                uint64_t(y) * kSize + uint64_t(x));
                const float jx = rng.nextFloat();
                const float jy = rng.nextFloat();
                glm::vec3 dir = camera.direction(x, y, jx, jy), origin = camera.origin();
                glm::dvec3 p = glm::dvec3(origin + dir * (-origin.y / dir.y));
                glm::dvec3 d = glm::dvec3(l.position) - p;
                double d2 = glm::dot(d, d);
                double cosTheta = std::max(0.0, d.y / std::sqrt(d2));
                expected += kAlbedo / kPiD * double(l.intensity) / (4.0 * kPiD * d2) * cosTheta;
            }
            expected /= kPasses;
            double rendered = img.at(x, y).x;
            sumRendered += rendered;
            sumExpected += expected;
            maxError = std::max(maxError, std::abs(rendered / expected - 1.0));
        }
    std::printf("[ gpu lights ] point closed form: max per-pixel error %.2e, mean ratio %.6f\n",
                maxError, sumRendered / sumExpected);
    EXPECT_LT(maxError, kClosedFormTolerance);
    EXPECT_EQ((*gpu)->validationMessageCount(), 0);
}

TEST(GpuLights, DefaultSceneWithItsSoftboxAgreesWithTheCpuWithinThreeSigma) {
    const std::string path = std::string(WAVELIT_RESOURCE_DIR) + "/scenes/ring_on_ground.wlscene";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << "default scene not present";
    auto loaded = scene::loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    auto scene = std::make_shared<scene::Scene>(std::move(loaded.value()));
    ASSERT_FALSE(scene->lighting.lights.empty()) << "the default scene should carry its softbox";
    constexpr int kSize = 64, kPasses = 6;
    RenderOptions options = gpuOptions(4, kSize);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto gpu = createGpuPathTracer(scene, bvh, options);
    ASSERT_TRUE(gpu.ok()) << gpu.error().message();
    auto cpu = createCpuPathTracer(scene, bvh, options);
    ASSERT_TRUE(cpu.ok()) << cpu.error().message();
    // Per-pass image means: pass k's mean is k·m_k − (k−1)·m_{k−1} of the running means. Their
    // spread gives the standard error of each tracer's mean.
    auto passMeans = [&](Integrator& t) {
        std::vector<double> means;
        double previous = 0.0;
        for (int k = 1; k <= kPasses; ++k) {
            util::ImageRGB img = render(t, 1);
            EXPECT_TRUE(allFinite(img));
            double running = meanLuminance(img);
            means.push_back(k * running - (k - 1) * previous);
            previous = running;
        }
        return means;
    };
    auto stats = [](const std::vector<double>& v, double& mean, double& stdError) {
        mean = 0.0;
        for (double x : v)
            mean += x;
        mean /= double(v.size());
        double var = 0.0;
        for (double x : v)
            var += (x - mean) * (x - mean);
        var /= double(v.size() - 1);
        stdError = std::sqrt(var / double(v.size()));
    };
    double gm, gse, cm, cse;
    stats(passMeans(**gpu), gm, gse);
    stats(passMeans(**cpu), cm, cse);
    const double sigma = std::sqrt(gse * gse + cse * cse);
    std::printf("[ gpu lights ] default scene 64x64: gpu %.5f +- %.5f, cpu %.5f +- %.5f\n", gm, gse,
                cm, cse);
    EXPECT_GT(gm, 0.0);
    // Same random streams make the two means nearly equal; 3σ is the statistical bound that
    // must hold even if they were independent. A floor of 1e-6 keeps a zero spread meaningful.
    EXPECT_LE(std::abs(gm - cm), 3.0 * std::max(sigma, 1e-6 * cm));
    EXPECT_EQ((*gpu)->validationMessageCount(), 0);
}

} // namespace
} // namespace wavelit::render
