// The Vulkan `wavelet` and `oracle` samplers (shaders/sampling/) judged on
// their own: their per-hit products are built differently from the CPU's (wavelet: dense at 16^2
// leaves; oracle: a coarser dense grid, see the GLSL), so the twin test cannot cover them.
// For the six shading configurations of direction_sampler_test (grazing 85 degrees, mirror-like
// r = 0.02, Lambert, ...) under the studio env and a sky with a 10^6 sun (and, for `wavelet`,
// whose policy takes mis's technique for every lobe wider than that sun, a 13-degree sun of a
// glossy lobe's extent, where the r = 0.2 lobe keeps the product), the GPU draws 40k
// directions per configuration and reports what its mixture was built from (weights, window,
// product pyramid). The pdf those pieces define is evaluated on the CPU (the env tables are the
// same object the GPU got; the BSDF is the C++ twin of the GLSL plugin); then:
//  - chi-square of the GPU's directions against that pdf (p > Sidak-corrected 0.01);
//  - the pdf the GPU returned with each direction equals that pdf at the direction (exactness of
//    the estimator's division, architecture.md §4);
//  - the pdf integrates to 1 (minus the BSDF's invalid mass);
//  - oracle only: the GPU's window is the CPU's chooseWindow for the exact axis, and its leaf
//    masses are the dense product the CPU tabulates over that window (brute force).
#include "render/testing/gpu_sampler_probe.h"
#include "render/sampling/oracle_sampler.h"
#include "render/testing/sampler_chi_square.h"
#include "render/testing/sampler_test_configs.h"
#include "render/testing/sampler_test_envs.h"
#include "util/image.h"
#include "vk/context.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace wavelit::render {
namespace {

using namespace testing_configs;

constexpr int kSamples = 40000;
const double kChiAlpha = util::sidakAlpha(0.01, 5 * kConfigs);
// The wide sun (env 2): as direction_sampler_test.cpp's, 13 degrees across, 10^4 x the sky.
constexpr double kWideSunDiameterDeg = 13.0;

// Oracle only: the GPU chose the window the CPU's chooseWindow picks for the exact axis, and its
// leaves are the dense product (env-weighted BRDF x cos times the env's averages) the CPU
// tabulates by brute force over that window.
void expectOracleLeavesMatchTheCpu(const GpuMixture& mix) {
    const SamplerEnvironment& env = *mix.env;
    const bool lambert = std::string(mix.material->brdf->name()) == "lambert";
    const glm::vec3 axisWorld = lambert ? mix.point.n : reflectionOf(mix.point);
    const glm::dvec3 axis = env.toLocal(glm::normalize(glm::dvec3(axisWorld)));
    const double cap = oracleCapHalfAngle(*mix.material->brdf, mix.material->params);
    const ProductWindow window =
        chooseWindow(env.map(), axis, cap, std::max(1, env.level() + 6 - kGpuOracleLevel));
    EXPECT_EQ(mix.k, window.k);
    EXPECT_EQ(mix.ox, window.ox);
    EXPECT_EQ(mix.oy, window.oy);
    ASSERT_EQ(mix.m, kGpuOracleLevel);
    if (mix.k != window.k || mix.ox != window.ox || mix.oy != window.oy)
        return;
    auto brdfCosLocal = [&](const glm::dvec3& d) {
        return mix.brdfCos(glm::vec3(env.toWorld(d)));
    };
    const wavelet::SquareGrid lobe =
        windowTabulateEnvWeighted(env, window, kGpuOracleLevel, brdfCosLocal, 2);
    const wavelet::SquareGrid envGrid = windowEnvGrid(env, window, kGpuOracleLevel);
    const int side = 1 << kGpuOracleLevel, off = ((1 << (2 * kGpuOracleLevel)) - 1) / 3;
    double cpuTotal = 0.0, largest = 0.0, worst = 0.0;
    for (int i = 0; i < side * side; ++i) {
        const double expected = lobe.values[size_t(i)] * envGrid.values[size_t(i)];
        cpuTotal += expected;
        largest = std::max(largest, expected);
        worst = std::max(worst, std::abs(mix.mass[size_t(off + i)] - expected));
    }
    ASSERT_GT(cpuTotal, 0.0);
    EXPECT_NEAR(mix.mass[0] / cpuTotal, 1.0, 1e-3);
    EXPECT_LT(worst, 1e-3 * largest) << "largest leaf " << largest;
}

// The configurations' materials, one per configuration (direction_sampler_test's).
std::vector<SamplerMaterial> configMaterials() {
    std::vector<SamplerMaterial> materials;
    for (const Config& c : kConfigList)
        materials.push_back(
            {c.name, plugins::findBrdf(c.brdf), {glm::vec3(0.9f, 0.8f, 0.7f), c.roughness}});
    return materials;
}

// The suns' direction: beside configuration 3's (glossy r = 0.2) reflection.
glm::vec3 caseSunDirection() {
    return glm::normalize(reflectionOf(shadingPoint(kConfigList[3], 3)) +
                          glm::vec3(0.0f, 0.14f, 0.0f));
}

// Env 0: the studio map turned 30 degrees; 1: a sky with a one-texel sun 10^6 x brighter;
// 2: a 13-degree sun 10^4 x the sky.
scene::Environment caseEnvironment(int env) {
    if (env == 0) {
        auto studio = loadDownsampledEnvironment(
            std::string(WAVELIT_RESOURCE_DIR) + "/envmaps/studio.exr", 256);
        EXPECT_TRUE(studio.ok());
        scene::Environment e = studio.ok() ? *studio : scene::Environment{};
        e.rotationDeg = 30.0f;
        return e;
    }
    if (env == 2)
        return makeSunSkyEnvironment(256, caseSunDirection(), 1e4, kWideSunDiameterDeg);
    return makeSunSkyEnvironment(256, caseSunDirection(), 1e6);
}

struct Case {
    SamplerKind kind;
    int env; // 0: studio, 1: one-texel sun, 2: 13-degree sun
};

class GpuProductSampler : public ::testing::TestWithParam<Case> {};

TEST_P(GpuProductSampler, ChiSquareAndExactPdfForEveryConfiguration) {
    const SamplerKind kind = GetParam().kind;
    const bool studio = GetParam().env == 0;
    const glm::vec3 sunDir = caseSunDirection();
    const scene::Environment envSource = caseEnvironment(GetParam().env);
    const std::vector<SamplerMaterial> materials = configMaterials();
    const auto tables = DirectionSamplerTables::build(envSource, materials, kind);
    const SamplerEnvironment& env = tables->environment();
    std::vector<ShadingPoint> points;
    for (int c = 0; c < kConfigs; ++c)
        points.push_back(shadingPoint(kConfigList[c], size_t(c)));
    auto ctx = vk::Context::create({"", true});
    ASSERT_TRUE(ctx.ok()) << ctx.error().message();
    ASSERT_TRUE((*ctx)->hasFloat64());
    auto probe = probeGpuSampler(**ctx, *tables, kind, points, kSamples);
    ASSERT_TRUE(probe.ok()) << probe.error().message();
    EXPECT_EQ(probe->validationMessages, 0);
    EXPECT_EQ((*ctx)->validationMessageCount(), 0);

    for (int c = 0; c < kConfigs; ++c) {
        SCOPED_TRACE(std::string(samplerKindName(kind)) + (studio ? " studio " : " sun ") +
                     kConfigList[c].name);
        const GpuMixture& mix = probe->mixtures[size_t(c)];
        const GpuProbeDraw* draws = &probe->draws[size_t(c) * kSamples];
        EXPECT_NEAR(mix.cProduct + mix.cBsdf + mix.cEnv, 1.0, 1e-6);
        if (GetParam().env == 2 && c == 3) {
            EXPECT_GT(mix.cProduct, 0.1); // glossy r = 0.2: the product
        }
        if (kind == SamplerKind::Oracle) {
            EXPECT_GT(mix.cProduct, 0.1); // the dense product is always in the mixture
            expectOracleLeavesMatchTheCpu(mix);
        }

        // The GPU's pdf with each draw is the mixture's pdf at the draw.
        int next = 0, mismatches = 0;
        for (int i = 0; i < kSamples; ++i) {
            if (draws[i].pdf < 0.0f)
                continue;
            const double expected = mix.pdf(draws[i].wi);
            if (std::abs(draws[i].pdf - expected) > 1e-3 * expected)
                ++mismatches;
        }
        // Float rounding of a drawn point across a texel edge (CPU tests see ~1e-7 per edge): the
        // GPU's pdf is taken at the double point it drew, this one at the float direction. The
        // oracle's mirror leaves are 2^-13 of the square, 2^5 x smaller than the wavelet's, so
        // more draws sit within rounding of an edge between leaves of very different mass.
        EXPECT_LE(mismatches, kSamples / 1000) << "pdf mismatches";

        SphereChiSquareOptions o;
        o.samples = kSamples;
        const float r = kConfigList[c].roughness;
        if (std::string(kConfigList[c].brdf) == "ggx" && r < 0.3f) {
            o.hotSpots = {reflectionOf(mix.point)};
            o.hotRadius = 10.0 * r * r + 0.005;
        }
        // The env share's pdf is constant on equirect texels, not on the integration grid
        // (direction_sampler_test.cpp, ChiSquareMatchesPdf): finer quadrature, same assertions.
        if (studio) {
            o.integrationLevel += 2;
            o.hotDepth -= 2;
        } else if (GetParam().env == 2) {
            o.texelSpot = sunDir; // the disc's rim (direction_sampler_test.cpp)
            o.texelSpotRadius = 0.5 * kWideSunDiameterDeg * util::kPi / 180.0 + 0.017;
            o.texelSpotDepth = 7;
        } else {
            o.texelSpot = sunDir;
            o.texelSpotRadius = 0.017;
            o.texelSpotDepth = 9;
        }
        o.toBinFrame = [&](const glm::dvec3& d) { return env.toLocal(d); };
        o.fromBinFrame = [&](const glm::dvec3& d) { return env.toWorld(d); };
        const auto result = sphereChiSquare(
            [&](float, float, float) -> std::optional<glm::vec3> {
                const GpuProbeDraw& d = draws[next++];
                if (d.pdf < 0.0f)
                    return std::nullopt;
                return d.wi;
            },
            [&](const glm::vec3& w) { return mix.pdf(w); }, o);
        EXPECT_GT(result.chi.pValue, kChiAlpha)
            << "chi2 " << result.chi.statistic << " dof " << result.chi.degreesOfFreedom;
        EXPECT_EQ(result.chi.observedOutsideSupport, 0.0);
        EXPECT_LE(result.integratedPdf, 1.0 + 1e-3);
        std::printf("[gpu %s chi2] %-6s %-13s p = %.3g (dof %d, integral %.4f, shares "
                    "product %.2f bsdf %.2f env %.2f, window k=%d m=%d + %d refined, %d pdf "
                    "mismatches)\n",
                    samplerKindName(kind), studio ? "studio" : "sun", kConfigList[c].name,
                    result.chi.pValue,
                    result.chi.degreesOfFreedom, result.integratedPdf, mix.cProduct, mix.cBsdf,
                    mix.cEnv, mix.k, mix.m, mix.refineLevels, mismatches);
    }
}

INSTANTIATE_TEST_SUITE_P(KindsAndEnvs, GpuProductSampler,
                         ::testing::Values(Case{SamplerKind::Wavelet, 0}, Case{SamplerKind::Wavelet, 1},
                                           Case{SamplerKind::Wavelet, 2},
                                           Case{SamplerKind::Oracle, 0}, Case{SamplerKind::Oracle, 1}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                             return std::string(i.param.kind == SamplerKind::Oracle ? "Oracle" : "Wavelet") +
                                    (i.param.env == 0 ? "Studio" : i.param.env == 1 ? "Sun" : "WideSun");
                         });

// Both tracers draw the camera vertex's `wavelet` NEE from one mixture: the C++ tracer's build
// (DirectionSampler with ProductBuild::Tracer) against the kernel's, as the probe reads it back,
// at every configuration under the three envs: the same technique shares, and the same pdf at
// the kernel's draws (to float rounding: the kernel builds in float, the C++ in double).
class GpuTracerProduct : public ::testing::TestWithParam<int> {};

TEST_P(GpuTracerProduct, CpuTracerBuildIsTheKernelsMixture) {
    const auto tables = DirectionSamplerTables::build(caseEnvironment(GetParam()),
                                                      configMaterials(), SamplerKind::Wavelet);
    std::vector<ShadingPoint> points;
    for (int c = 0; c < kConfigs; ++c)
        points.push_back(shadingPoint(kConfigList[c], size_t(c)));
    auto ctx = vk::Context::create({"", true});
    ASSERT_TRUE(ctx.ok()) << ctx.error().message();
    constexpr int kDraws = 4000;
    auto probe = probeGpuSampler(**ctx, *tables, SamplerKind::Wavelet, points, kDraws);
    ASSERT_TRUE(probe.ok()) << probe.error().message();
    EXPECT_EQ(probe->validationMessages, 0);
    EXPECT_EQ((*ctx)->validationMessageCount(), 0);
    int products = 0;
    for (int c = 0; c < kConfigs; ++c) {
        SCOPED_TRACE(kConfigList[c].name);
        const GpuMixture& gpu = probe->mixtures[size_t(c)];
        const DirectionSampler cpu(*tables, SamplerKind::Wavelet, points[size_t(c)],
                                   ProductBuild::Tracer);
        double share[3] = {0.0, 0.0, 0.0}; // product, bsdf, env
        for (const ComponentPdf& p : cpu.componentPdfs(reflectionOf(points[size_t(c)]))) {
            const std::string name = p.technique;
            share[name == "product" ? 0 : name == "bsdf" ? 1 : 2] += p.weight;
        }
        EXPECT_NEAR(share[0], gpu.cProduct, 1e-4);
        EXPECT_NEAR(share[1], gpu.cBsdf, 1e-4);
        EXPECT_NEAR(share[2], gpu.cEnv, 1e-4);
        products += gpu.cProduct > 0.0 ? 1 : 0;
        int drawn = 0, mismatches = 0;
        double worst = 0.0;
        for (int i = 0; i < kDraws; ++i) {
            const GpuProbeDraw& d = probe->draws[size_t(c) * kDraws + size_t(i)];
            if (d.pdf < 0.0f)
                continue;
            ++drawn;
            const double expected = gpu.pdf(d.wi), got = cpu.pdfDouble(d.wi);
            const double relative = std::abs(got - expected) / expected;
            worst = std::max(worst, relative);
            if (relative > 1e-3)
                ++mismatches;
        }
        // Draws within float rounding of a leaf edge, as in the test above.
        EXPECT_LE(mismatches, drawn / 1000 + 1) << "worst relative pdf difference " << worst;
        std::printf("[tracer product twin] env %d %-13s shares %.3f/%.3f/%.3f, %d of %d pdfs "
                    "differ > 1e-3 (worst %.2g)\n",
                    GetParam(), kConfigList[c].name, gpu.cProduct, gpu.cBsdf, gpu.cEnv,
                    mismatches, drawn, worst);
    }
    // The one-texel sun hands every lobe to mis's technique (EnvMis); the others keep products.
    if (GetParam() != 1) {
        EXPECT_GT(products, 0);
    }
}

INSTANTIATE_TEST_SUITE_P(Envs, GpuTracerProduct, ::testing::Values(0, 1, 2),
                         [](const ::testing::TestParamInfo<int>& i) {
                             return std::string(i.param == 0   ? "Studio"
                                                : i.param == 1 ? "Sun"
                                                               : "WideSun");
                         });

} // namespace
} // namespace wavelit::render
