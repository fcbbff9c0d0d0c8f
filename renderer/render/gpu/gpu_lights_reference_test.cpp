// Analytic lights on the Vulkan path tracer against references that do not come from its CPU
// twin's image: a closed form (a Lambert plane under a point light) and, on the default scene with
// its softbox, the CPU tracer's mean within three standard errors. Scene helpers:
// gpu_lights_test_support.h.
#include "render/gpu/gpu_lights_test_support.h"

#include "render/reference/cpu_camera.h"
#include "render/testing/cpu_analytic_scenes.h"
#include "render/gpu/gpu_path_tracer.h"
#include "render/session/integrator_factory.h"
#include "scene/bvh.h"
#include "scene/scene_io.h"
#include "util/path_sampler.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

using namespace gpu_lights_test;

constexpr double kPiD = 3.14159265358979323846;
// The closed form's tolerance (the brief): a delta light with bounces = 1 has no Monte Carlo
// noise once the camera jitter is replayed, so only float rounding remains.
constexpr double kClosedFormTolerance = 0.01;

TEST(GpuLights, LambertPlaneUnderAPointLightIsTheClosedForm) {
    // Direct lighting only (bounces = 1), black sky: each sample is ρ/π · Φ/(4π d²) · cos θ at
    // the point its camera ray hits, which the test finds by replaying the camera jitter.
    scene::Material m;
    m.baseColor = glm::vec3(kAlbedo);
    auto s = makePlaneScene(m);
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
                util::PathSampler rng(util::PathSampler::seedKey(options.seed),
                                      uint32_t(y * kSize + x), uint32_t(pass));
                const auto [jx, jy] = rng.next2D();
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
