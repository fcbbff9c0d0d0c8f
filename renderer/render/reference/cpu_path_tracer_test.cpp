// The CPU reference tracer against closed forms: exact emission and environment values at zero
// bounces, the closed emissive sphere (Le Σ ρ^k: multi-bounce + Russian roulette unbiased),
// error reporting, and determinism (a pixel is a function of seed, pass and pixel only).
// The furnace tests (sphere in a constant environment) live in tests/furnace_test.cpp.
#include "render/reference/cpu_path_tracer.h"

#include "render/testing/cpu_analytic_scenes.h"
#include "render/reference/cpu_camera.h"
#include "render/lights/cpu_environment.h"
#include "render/session/integrator_factory.h"
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>

namespace wavelit::render {
namespace {

// Float rounding of a handful of products (radiance values of order 1).
constexpr float kFloatTolerance = 1e-5f;

std::unique_ptr<CpuPathTracer> makeTracer(std::shared_ptr<const scene::Scene> scene,
                                          RenderOptions options, int threads = 0) {
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    auto tracer = CpuPathTracer::create(scene, bvh, options, threads);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error().message());
    return tracer.ok() ? std::move(tracer.value()) : nullptr;
}

RenderOptions smallOptions(int size, int bounces) {
    RenderOptions o;
    o.width = size;
    o.height = size;
    o.bounces = bounces;
    o.seed = 17;
    o.device = DeviceChoice::Cpu;
    return o;
}

TEST(CpuPathTracer, AcceptsEverySamplerAndRejectsUnknownBrdfs) {
    auto scene = makeFurnaceScene(scene::Material{}, glm::vec3(1.0f), 16, 8);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
    // Every sampler kind is implemented (cpu_path_tracer_sampler_test.cpp checks their means).
    for (SamplerKind kind : allSamplerKinds()) {
        RenderOptions o = smallOptions(8, 1);
        o.sampler = kind;
        EXPECT_TRUE(createCpuPathTracer(scene, bvh, o).ok()) << samplerKindName(kind);
    }

    auto bad = std::make_shared<scene::Scene>(*scene);
    bad->materials[0].brdf = "toon";
    bad->materials[0].name = "shiny";
    auto r2 = createCpuPathTracer(bad, bvh, smallOptions(8, 1));
    ASSERT_FALSE(r2.ok());
    EXPECT_EQ(r2.error().kind, util::ErrorKind::Unsupported);
    EXPECT_NE(r2.error().message().find("shiny"), std::string::npos);
    EXPECT_NE(r2.error().message().find("toon"), std::string::npos);

    RenderOptions zero = smallOptions(0, 1);
    auto r3 = createCpuPathTracer(scene, bvh, zero);
    ASSERT_FALSE(r3.ok());
    EXPECT_EQ(r3.error().kind, util::ErrorKind::Invalid);
}

TEST(CpuPathTracer, ZeroBouncesSeeEmissionAndEnvironmentExactly) {
    scene::Material m;
    m.emission = glm::vec3(2.0f, 3.0f, 4.0f);
    auto scene = makeFurnaceScene(m, glm::vec3(0.25f, 0.5f, 0.75f), 32, 16);
    auto tracer = makeTracer(scene, smallOptions(32, 0));
    ASSERT_TRUE(tracer);
    ASSERT_TRUE(tracer->renderPass().ok());
    ASSERT_TRUE(tracer->renderPass().ok());
    auto img = tracer->image();
    ASSERT_TRUE(img.ok());
    EXPECT_EQ(tracer->samplesPerPixel(), 2);
    // Centre: the sphere; corner: the environment (the sphere fills ~70% of the height).
    glm::vec3 centre = img->at(16, 16), corner = img->at(0, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(centre[c], m.emission[c], kFloatTolerance);
        EXPECT_NEAR(corner[c], 0.25f * (c + 1), kFloatTolerance);
    }
}

TEST(CpuPathTracer, ClosedEmissiveSphereSumsTheBounceSeries) {
    // Inside a closed Lambert sphere with albedo ρ and emission Le, every path sees Le at each of
    // its B + 1 vertices, weighted ρ^k: Le (1 + ρ + ... + ρ^B). bounces = 1 has no roulette, so
    // every sample is exact; bounces = 6 exercises Russian roulette (depth ≥ 2), unbiased.
    scene::Material m;
    m.baseColor = glm::vec3(0.5f, 0.7f, 0.9f);
    m.emission = glm::vec3(1.0f);
    auto scene = makeClosedSphereScene(m);

    auto exact = makeTracer(scene, smallOptions(16, 1));
    ASSERT_TRUE(exact->renderPass().ok());
    auto img1 = exact->image();
    for (const glm::vec3& p : img1->pixels)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], 1.0f + m.baseColor[c], kFloatTolerance);

    const int bounces = 6, size = 32, passes = 32;
    auto tracer = makeTracer(scene, smallOptions(size, bounces));
    // Per-sample statistics through samplePixel: the mean over all pixels and passes and its
    // standard error.
    glm::dvec3 sum(0.0), sum2(0.0);
    for (int pass = 0; pass < passes; ++pass)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                glm::dvec3 v(tracer->samplePixel(x, y, pass));
                sum += v;
                sum2 += v * v;
            }
    const double n = double(passes) * size * size;
    for (int c = 0; c < 3; ++c) {
        double rho = m.baseColor[c], expected = 0.0;
        for (int k = 0; k <= bounces; ++k) expected += std::pow(rho, k);
        double mean = sum[c] / n, se = std::sqrt((sum2[c] / n - mean * mean) / n);
        EXPECT_NEAR(mean, expected, 4.0 * se) << "channel " << c << " se " << se;
        EXPECT_GT(se, 0.0); // roulette really ran (a zero spread would mean it never fired)
    }
}

TEST(CpuPathTracer, ImageIsTheMeanOfSamplePixelWhateverTheThreadCount) {
    scene::Material m;
    m.brdf = "ggx";
    m.roughness = 0.3f;
    auto scene = makeFurnaceScene(m, glm::vec3(1.0f), 32, 16);
    auto one = makeTracer(scene, smallOptions(24, 3), 1);
    auto many = makeTracer(scene, smallOptions(24, 3), 5);
    ASSERT_EQ(one->threadCount(), 1);
    for (int pass = 0; pass < 3; ++pass) {
        ASSERT_TRUE(one->renderPass().ok());
        ASSERT_TRUE(many->renderPass().ok());
    }
    auto a = one->image(), b = many->image();
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            ASSERT_EQ(a->at(x, y), b->at(x, y)) << x << "," << y;
            glm::dvec3 mean(0.0);
            for (int pass = 0; pass < 3; ++pass) mean += glm::dvec3(one->samplePixel(x, y, pass));
            glm::vec3 expect(mean / 3.0);
            ASSERT_NEAR(a->at(x, y).x, expect.x, kFloatTolerance);
        }
    // A reset starts over: the first pass after it equals the first pass before.
    one->resetAccumulation();
    EXPECT_EQ(one->samplesPerPixel(), 0);
    ASSERT_TRUE(one->renderPass().ok());
    EXPECT_EQ(one->image()->at(12, 12), one->samplePixel(12, 12, 0));
    // Different seeds give different paths.
    RenderOptions other = smallOptions(24, 3);
    other.seed = 18;
    auto reseeded = makeTracer(scene, other);
    EXPECT_NE(reseeded->samplePixel(12, 12, 0), one->samplePixel(12, 12, 0));
}

TEST(CpuPathTracer, HardCasesStayFiniteAndNonNegative) {
    // architecture.md §8's hard cases at once: an HDR sun 10^6× the sky, a black lower half, a
    // mirror-like GGX sphere (r = 0.02) on a diffuse ground without vertex normals (n_g path),
    // grazing views at the sphere's rim, four bounces with roulette.
    auto env = std::make_shared<util::ImageRGB>(64, 32, glm::vec3(0.0f));
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x) env->at(x, y) = glm::vec3(0.3f, 0.5f, 1.0f);
    env->at(40, 5) = glm::vec3(1e6f);
    for (float r : {0.02f, 1.0f}) {
        scene::Material sphere;
        sphere.brdf = "ggx";
        sphere.roughness = r;
        sphere.baseColor = glm::vec3(0.9f);
        auto s = makeFurnaceScene(sphere, glm::vec3(1.0f), 48, 24);
        s->lighting.environment.image = env;
        s->camera.position = glm::vec3(0.0f, 0.6f, 4.0f);
        scene::Material ground;
        ground.id = 10;
        ground.baseColor = glm::vec3(0.7f);
        s->materials.push_back(ground);
        scene::Object plane;
        plane.id = 11;
        plane.materialId = 10;
        auto mesh = std::make_shared<scene::TriangleMesh>();
        mesh->positions = {{-5, -1, -5}, {5, -1, -5}, {5, -1, 5}, {-5, -1, 5}};
        mesh->indices = {0, 2, 1, 0, 3, 2};
        plane.mesh = mesh;
        s->objects.push_back(plane);
        auto tracer = makeTracer(s, smallOptions(32, 4));
        for (int pass = 0; pass < 4; ++pass) ASSERT_TRUE(tracer->renderPass().ok());
        auto img = tracer->image();
        double total = 0.0;
        for (const glm::vec3& p : img->pixels)
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(p[c])) << "r=" << r;
                ASSERT_GE(p[c], 0.0f);
                total += p[c];
            }
        EXPECT_GT(total, 0.0);
    }
}

TEST(CpuEnvironment, NearestTexelWithRotationIntensityAndTint) {
    auto image = std::make_shared<util::ImageRGB>(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) image->at(x, y) = glm::vec3(float(x), float(y), 1.0f);
    scene::Environment env;
    env.image = image;
    env.intensity = 2.0f;
    env.tint = glm::vec3(1.0f, 0.5f, 1.0f);
    CpuEnvironment plain(env);
    // +X: u = 0.5 → column 4; just above the horizon → row 1. Scaled by intensity × tint.
    glm::vec3 d = glm::normalize(glm::vec3(1.0f, 0.1f, 0.0f));
    EXPECT_EQ(plain.radiance(d), glm::vec3(8.0f, 1.0f, 2.0f));
    // +Z: atan2(1, 0) = π/2 → u = 0.75 → column 6. Straight up → row 0; down → last row.
    EXPECT_EQ(plain.radiance(glm::vec3(0.0f, 0.0f, 1.0f)).x, 12.0f);
    EXPECT_EQ(plain.radiance(glm::vec3(0.0f, 1.0f, 0.0f)).y, 0.0f);
    EXPECT_EQ(plain.radiance(glm::vec3(0.0f, -1.0f, 0.0f)).y, 3.0f);
    // −X: atan2(0, −1) = π → u = 1 → clamped to the last column.
    EXPECT_EQ(plain.radiance(glm::vec3(-1.0f, 0.0f, 0.0f)).x, 14.0f);

    // Yaw 90° moves what was seen along +Z to R_y(90°)·(+Z) = +X.
    env.rotationDeg = 90.0f;
    CpuEnvironment rotated(env);
    EXPECT_EQ(rotated.radiance(glm::normalize(glm::vec3(1.0f, 0.0f, 0.01f))).x, 12.0f);

    scene::Environment constant;
    constant.intensity = 3.0f;
    constant.tint = glm::vec3(0.1f, 0.2f, 0.3f);
    glm::vec3 c = CpuEnvironment(constant).radiance(glm::vec3(0.3f, 0.4f, 0.866f));
    EXPECT_NEAR(c.y, 0.6f, kFloatTolerance);
}

TEST(CpuCamera, RaysFollowTheEstimatorConvention) {
    scene::Camera cam;
    cam.position = glm::vec3(0.0f, 0.0f, 0.0f);
    cam.target = glm::vec3(0.0f, 0.0f, -1.0f);
    cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
    cam.verticalFovDeg = 90.0f; // tanHalf = 1
    CpuCamera camera(cam, 20, 10);
    // Image centre (x = 10, jitter 0) looks along forward.
    glm::vec3 c = camera.direction(10, 5, 0.0f, 0.0f);
    EXPECT_NEAR(glm::length(c - glm::vec3(0, 0, -1)), 0.0f, kFloatTolerance);
    // Top-left corner: sx = −aspect = −2, sy = +1 (y = 0 is the top row).
    glm::vec3 tl = camera.direction(0, 0, 0.0f, 0.0f);
    glm::vec3 expected = glm::normalize(glm::vec3(-2.0f, 1.0f, -1.0f));
    EXPECT_NEAR(glm::length(tl - expected), 0.0f, kFloatTolerance);
}

} // namespace
} // namespace wavelit::render
