// Issue 20: env next-event estimation keeps every sample of a diffuse scene under a sun bounded,
// `mis`'s roulette on its shadow ray keeps the mean and reads no intensity (issue 12), and the
// outlier tracer finds a known outlier path.
//
// The bound (docs/estimator.md "Direction samplers"): the env technique's pdf is the conservative
// luminance table over its integral E (p_env >= lum(L) / E wherever L > 0), so an env-NEE term of
// a Lambert vertex is at most f cos L / p_env <= albedo/pi x E x (max RGB / luminance of the map);
// env light the BSDF continuation finds is weighted p_b^2 / (p_b^2 + p_env^2) <= p_b / (2 p_env),
// so it is at most half that. The continuation's throughput factor is albedo (cosine sampling)
// and Russian roulette scales a grey throughput up to at most 1, so with B scattering vertices a
// sample is at most (B + 1/2) x albedo/pi x E x ratio. Before env NEE, paths continued along
// env-drawn directions: `env` carried f cos / p_env ~ 20 into dim sky and `mis` survived Russian
// roulette with probability 3e-4 after a sun-drawn direction, giving samples ~10^4 x the pixel.
#include "render/testing/cpu_analytic_scenes.h"
#include "render/reference/cpu_path_tracer.h"
#include "render/reference/outlier_tracer.h"
#include "render/sampling/sampler_environment.h"
#include "render/sampling/sampler_constants.h"
#include "render/testing/cpu_test_tracer.h"
#include "render/testing/pixel_moments.h"
#include "render/testing/sampler_test_envs.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <utility>

namespace wavelit::render {
namespace {

constexpr float kSphereAlbedo = 0.6f, kGroundAlbedo = 0.5f;

// A Lambert sphere on a large Lambert ground, seen from above so that every camera ray hits
// geometry (a camera ray that sees the sun directly is not a scattered sample).
std::shared_ptr<scene::Scene> diffuseSceneUnder(const scene::Environment& env) {
    scene::Material sphere;
    sphere.id = 1;
    sphere.name = "sphere";
    sphere.brdf = "lambert";
    sphere.baseColor = glm::vec3(kSphereAlbedo);
    auto s = makeFurnaceScene(sphere, glm::vec3(1.0f), 32, 16);
    s->lighting.environment = env;
    s->camera.position = glm::vec3(0.0f, 4.0f, 2.5f);
    s->camera.target = glm::vec3(0.0f, -0.5f, 0.0f);
    s->camera.verticalFovDeg = 40.0f;
    scene::Material ground;
    ground.id = 2;
    ground.name = "ground";
    ground.brdf = "lambert";
    ground.baseColor = glm::vec3(kGroundAlbedo);
    s->materials.push_back(ground);
    scene::Object plane;
    plane.id = 3;
    plane.name = "ground";
    plane.materialId = 2;
    auto mesh = std::make_shared<scene::TriangleMesh>();
    mesh->positions = {{-60, -1, -60}, {60, -1, -60}, {60, -1, 60}, {-60, -1, 60}};
    mesh->normals.assign(4, glm::vec3(0, 1, 0));
    mesh->indices = {0, 2, 1, 0, 3, 2};
    plane.mesh = mesh;
    s->objects.push_back(plane);
    return s;
}

std::unique_ptr<CpuPathTracer> tracerFor(std::shared_ptr<const scene::Scene> scene,
                                         SamplerKind kind, int size, int bounces) {
    RenderOptions o;
    o.width = o.height = size;
    o.bounces = bounces;
    o.seed = 5;
    o.device = DeviceChoice::Cpu;
    o.sampler = kind;
    return makeCpuTestTracer(std::move(scene), o);
}

// max over texels of max(R, G, B) / luminance (texels with light).
double rgbOverLuminance(const util::ImageRGB& img) {
    double r = 1.0;
    for (const glm::vec3& p : img.pixels) {
        const double l = util::luminance(p);
        if (l > 0.0) r = std::max(r, double(std::max(p.r, std::max(p.g, p.b))) / l);
    }
    return r;
}

TEST(EnvNee, DiffuseSamplesStayUnderTheEnvIntegralBound) {
    // A sky with a 0.53 degree sun at 10^6 x the sky mean (one texel of a 64-wide map).
    const scene::Environment env =
        makeSunSkyEnvironment(64, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e6, 0.53);
    const auto scene = diffuseSceneUnder(env);
    const double ratio = rgbOverLuminance(*env.image);
    constexpr int kSize = 24, kPasses = 48;
    for (int bounces : {1, 4}) {
        for (SamplerKind kind : {SamplerKind::Env, SamplerKind::Mis}) {
            auto tracer = tracerFor(scene, kind, kSize, bounces);
            ASSERT_TRUE(tracer);
            const SamplerEnvironment& table = tracer->samplerTables()->environment();
            ASSERT_TRUE(table.hasLight());
            // E: the integral over the sphere of the luminance table the env technique samples.
            const double integral = table.cellAverage(0, 0, 0) * 4.0 * std::numbers::pi;
            const double oneVertex = double(std::max(kSphereAlbedo, kGroundAlbedo)) /
                                     std::numbers::pi * integral * ratio;
            const double bound = (bounces + 0.5) * oneVertex;
            double largest = 0.0, sum = 0.0;
            for (int pass = 0; pass < kPasses; ++pass)
                for (int y = 0; y < kSize; ++y)
                    for (int x = 0; x < kSize; ++x) {
                        const glm::vec3 v = tracer->samplePixel(x, y, pass);
                        ASSERT_TRUE(std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b));
                        largest = std::max(largest, double(std::max(v.r, std::max(v.g, v.b))));
                        sum += util::luminance(v);
                    }
            const double mean = sum / (double(kPasses) * kSize * kSize);
            std::printf("[env nee] %-4s bounces %d: largest sample %.4g, bound %.4g (%.3g of it), "
                        "image mean %.4g\n",
                        samplerKindName(kind), bounces, largest, bound, largest / bound, mean);
            EXPECT_LE(largest, bound * 1.001) << samplerKindName(kind) << " bounces " << bounces;
            EXPECT_GT(mean, 0.0);
        }
    }
}

// `mis`'s Russian roulette on the env shadow ray (sampler_constants.h kMisEnvRoulette) is
// unbiased: a dark Lambert sphere (albedo 0.04) in a white furnace, one bounce. Every env-NEE
// term there has max(beta f) cos w <= 0.04/pi < kMisEnvRoulette (a constant env is spread: its
// c is kMisEnvRoulette itself, misEnvRoulette), so every shadow ray plays the
// roulette; `bsdf` has no env NEE and no roulette. The two image means agree within 4 sigma
// (dropping the 1/p of the survivors: z = -5.6 at kMisEnvRoulette = 0.02).
TEST(EnvNee, MisShadowRayRouletteKeepsTheMean) {
    scene::Material dark;
    dark.id = 1;
    dark.name = "dark";
    dark.brdf = "lambert";
    dark.baseColor = glm::vec3(0.04f);
    static_assert(0.04 / std::numbers::pi < kMisEnvRoulette, "every shadow ray must play");
    const auto scene = makeFurnaceScene(dark, glm::vec3(1.0f), 32, 16);
    constexpr int kSize = 24, kPasses = 256;
    PixelMoments m[2];
    const SamplerKind kinds[2] = {SamplerKind::Mis, SamplerKind::Bsdf};
    for (int k = 0; k < 2; ++k) {
        auto tracer = tracerFor(scene, kinds[k], kSize, 1);
        ASSERT_TRUE(tracer);
        m[k] = pixelMoments(*tracer, kSize, kSize, kPasses, MomentChannel::Luminance);
    }
    const double z = (m[0].mean - m[1].mean) / std::hypot(m[0].standardError, m[1].standardError);
    std::printf("[env nee] furnace albedo 0.04: mis %.6g, bsdf %.6g, z %.2f\n", m[0].mean,
                m[1].mean, z);
    EXPECT_LT(std::abs(z), 4.0);
    EXPECT_GT(m[0].mean, 0.0);
}

// A sky whose light the sun holds: `mis`'s roulette constant c is scaled down there
// (sampler_constants.h misEnvRoulette), so the tests below exercise the concentration rule.
scene::Environment rouletteSunSky(float intensity, const glm::vec3& tint) {
    scene::Environment env =
        makeSunSkyEnvironment(128, glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)), 1e4, 2.0);
    env.intensity = intensity;
    env.tint = tint;
    return env;
}

// The roulette constant reads the env's shape only: its effective solid angle (integral L)^2 /
// integral L^2 is invariant under the env's intensity and a grey tint, so p is too (LightMix,
// LightRemix: each path's estimate linear in every intensity). A constant env (4 pi sr) keeps
// kMisEnvRoulette; the sun sky gets less, and never below kMisEnvRouletteMinScale of it.
TEST(EnvNee, MisRouletteConstantIsScaleInvariantAndFollowsTheEnvsConcentration) {
    const SamplerEnvironment base = SamplerEnvironment::build(rouletteSunSky(1.0f, glm::vec3(1.0f)));
    const double omega = base.effectiveSolidAngle();
    const float c = misEnvRoulette(omega);
    std::printf("[env nee] sun sky: effective solid angle %.5g sr, roulette c %.5g\n", omega, c);
    ASSERT_LT(omega, kMisEnvRouletteSolidAngle);
    EXPECT_LT(c, float(kMisEnvRoulette));
    EXPECT_GE(c, float(kMisEnvRoulette * kMisEnvRouletteMinScale));
    EXPECT_NEAR(c, kMisEnvRoulette * omega / kMisEnvRouletteSolidAngle, 1e-6);
    for (const auto& [intensity, tint] :
         {std::pair{2.0f, glm::vec3(1.0f)}, std::pair{3.7f, glm::vec3(1.0f)},
          std::pair{1.0f, glm::vec3(0.3f)}, std::pair{1e3f, glm::vec3(0.01f)}}) {
        const SamplerEnvironment scaled = SamplerEnvironment::build(rouletteSunSky(intensity, tint));
        // Equal up to the float rounding of the tables' luminance (exact at 2x: a power of 2).
        EXPECT_NEAR(scaled.effectiveSolidAngle(), omega, 1e-6 * omega) << intensity;
        EXPECT_NEAR(misEnvRoulette(scaled.effectiveSolidAngle()), c, 1e-6f * c) << intensity;
    }
    scene::Environment furnace; // constant white: 4 pi sr, the spread end
    furnace.intensity = 5.0f;
    const SamplerEnvironment flat = SamplerEnvironment::build(furnace);
    EXPECT_NEAR(flat.effectiveSolidAngle(), 4.0 * std::numbers::pi, 1e-3);
    EXPECT_EQ(misEnvRoulette(flat.effectiveSolidAngle()), float(kMisEnvRoulette));
    EXPECT_EQ(misEnvRoulette(1e-6), float(kMisEnvRoulette * kMisEnvRouletteMinScale));
}

// Under the sun sky, where c differs from kMisEnvRoulette, the roulette keeps the mean: dark
// Lambert sphere and ground (albedo 0.02: max(beta f) cos w <= 0.02/pi < c, so every env shadow
// ray of this one-bounce scene plays), `mis` against `env` (light sampling alone, no roulette)
// within 4 sigma. And each path's estimate is linear in the env's intensity: at 2x (every number
// of the tables scales exactly) the image is bit for bit 2x, coins and all.
TEST(EnvNee, MisRouletteUnderASunKeepsTheMeanAndIsLinearInTheIntensity) {
    constexpr float kDark = 0.02f;
    auto sceneAt = [&](float intensity) {
        auto s = diffuseSceneUnder(rouletteSunSky(intensity, glm::vec3(1.0f)));
        for (scene::Material& m : s->materials) m.baseColor = glm::vec3(kDark);
        return s;
    };
    const auto scene = sceneAt(1.0f);
    constexpr int kSize = 24, kPasses = 256;
    PixelMoments m[2];
    const SamplerKind kinds[2] = {SamplerKind::Mis, SamplerKind::Env};
    for (int k = 0; k < 2; ++k) {
        auto tracer = tracerFor(scene, kinds[k], kSize, 1);
        ASSERT_TRUE(tracer);
        const float c = misEnvRoulette(tracer->samplerTables()->environment().effectiveSolidAngle());
        ASSERT_LT(kDark / std::numbers::pi, c) << "every shadow ray must play";
        ASSERT_LT(c, float(kMisEnvRoulette)) << "the scaled constant, not the old one";
        m[k] = pixelMoments(*tracer, kSize, kSize, kPasses, MomentChannel::Luminance);
    }
    const double z = (m[0].mean - m[1].mean) / std::hypot(m[0].standardError, m[1].standardError);
    std::printf("[env nee] sun sky albedo %.2f: mis %.6g +- %.2g, env %.6g +- %.2g, z %.2f\n",
                kDark, m[0].mean, m[0].standardError, m[1].mean, m[1].standardError, z);
    EXPECT_LT(std::abs(z), 4.0);
    EXPECT_GT(m[0].mean, 0.0);

    auto once = tracerFor(scene, SamplerKind::Mis, kSize, 1);
    auto twice = tracerFor(sceneAt(2.0f), SamplerKind::Mis, kSize, 1);
    ASSERT_TRUE(once && twice);
    int lit = 0;
    for (int pass = 0; pass < 8; ++pass)
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec3 a = once->samplePixel(x, y, pass);
                const glm::vec3 b = twice->samplePixel(x, y, pass);
                ASSERT_EQ(b, 2.0f * a) << x << "," << y << " pass " << pass;
                lit += a != glm::vec3(0.0f);
            }
    EXPECT_GT(lit, kSize * kSize); // survivors: the comparison saw estimates, not only zeros
}

TEST(OutlierTracer, FindsTheKnownOutlierPath) {
    // Black sky with one sun texel: with `bsdf` sampling a ground pixel's samples are 0 except
    // when its cosine-sampled direction lands in the sun texel, albedo x L_sun: the outliers, and
    // their path is known: camera -> ground (bsdf) -> escape into the sun.
    auto img = std::make_shared<util::ImageRGB>(32, 16, glm::vec3(0.0f));
    constexpr float kSun = 1e6f;
    img->at(5, 3) = glm::vec3(kSun);
    scene::Environment env;
    env.image = img;
    auto scene = diffuseSceneUnder(env);
    scene->objects.erase(scene->objects.begin()); // the ground alone
    auto tracer = tracerFor(scene, SamplerKind::Bsdf, 16, 1);
    ASSERT_TRUE(tracer);
    constexpr int kCount = 4;
    OutlierMonitor monitor(16, 16, kCount);
    for (int pass = 0; pass < 64; ++pass) {
        ASSERT_TRUE(tracer->renderPass().ok());
        auto mean = tracer->image();
        ASSERT_TRUE(mean.ok());
        monitor.addPass(*mean);
    }
    const std::vector<OutlierSample> outliers = monitor.outliers();
    ASSERT_EQ(outliers.size(), size_t(kCount));
    RenderOptions o;
    o.width = o.height = 16;
    o.bounces = 1;
    o.seed = 5;
    o.sampler = SamplerKind::Bsdf;
    auto paths = traceOutlierPaths(*scene, o, outliers);
    ASSERT_TRUE(paths.ok());
    for (size_t k = 0; k < outliers.size(); ++k) {
        const OutlierSample& s = outliers[k];
        const PathRecord& p = (*paths)[k];
        EXPECT_NEAR(s.value.g, kGroundAlbedo * kSun, 1e-3 * kSun) << "rank " << k;
        // The re-trace is the same path: same stream, same value.
        EXPECT_NEAR(p.value.g, s.value.g, 1e-3 * s.value.g) << "rank " << k;
        ASSERT_EQ(p.vertices.size(), 1u);
        EXPECT_EQ(p.vertices[0].material, "ground");
        EXPECT_EQ(p.vertices[0].technique, "bsdf");
        ASSERT_EQ(p.events.size(), 1u);
        EXPECT_EQ(p.events[0].kind, "env-escape");
        EXPECT_EQ(p.events[0].vertex, 0);
        EXPECT_FLOAT_EQ(p.events[0].radiance.g, kSun);
        EXPECT_NEAR(p.events[0].fcos.g / p.events[0].pdf, kGroundAlbedo, 1e-4);
    }
    const std::string json = outliersJson(o, "test", monitor.passes(), outliers, *paths,
                                          *tracer->image());
    EXPECT_NE(json.find("\"env-escape\""), std::string::npos);
    EXPECT_NE(json.find("\"technique\": \"bsdf\""), std::string::npos);
}

} // namespace
} // namespace wavelit::render
