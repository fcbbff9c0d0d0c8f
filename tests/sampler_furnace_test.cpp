// The white furnace for every direction sampler (issue 6): each `--sampler` kind on the CPU
// reference tracer must estimate the same integral, judged on the sphere's total (the furnace and
// its albedo tables: furnace_test_support.h).
#include "furnace_test_support.h"

#include "render/reference/cpu_camera.h"
#include "render/reference/cpu_path_tracer.h"
#include "render/reference/cpu_surface.h"
#include "render/sampling/direction_sampler.h"
#include "render/session/integrator_factory.h"

#include "plugins/brdf.h"
#include "plugins/brdf_table.h"
#include "plugins/testing/brdf_albedo.h"
#include "util/hemisphere_sampling.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace wavelit {
namespace {

using namespace furnace_test;

// ---- Every direction sampler (issue 6): the same furnace, judged on the sphere's total ----
// Each `--sampler` kind draws differently but must estimate the same integral, so the furnace
// holds for all of them. Per material and sampler, the sum over sphere pixels of the rendered
// image against the sum of the expectations (a per-pixel 1% bound would need each pixel's noise
// under 1%: thousands of passes for the noisy kinds). The standard error of that sum comes from
// the spread of its per-pass values (one sample per pixel per pass). The bound is only a test
// if the noise is well under it, so each case also asserts sigma <= 1% / 3: its pass count (the
// table below, from measured per-pass spreads) buys that precision and no more, at 32x32.
// Cases whose sampler cannot reach that precision in reasonable time on this scene are marked
// Unbiased: they check the ratio within 4 sigma and print the passes 1% would need (uniform,
// cosine and env on GGX r = 0.3: 8-17k passes; a lobe of half-width ~10 degrees found by chance
// gives ~50x the per-pass sigma of bsdf). Left out, as not even unbiasedness is checkable in
// reasonable time: uniform, cosine and env on GGX r = 0.05 (half-width ~0.3 degrees: after 64
// passes uniform read 0.26 +- 0.12 and env 0.11 +- 0.07, the sample spread missing the rare huge
// values; 1% would need 1e5-1e6 passes); and the oracle on more than two materials (its dense
// 128^2 product per shading point costs ~3 ms: a 32x32 pass takes 2.5-3 s on 2 cores; measured
// at 6 passes: r = 1 1.0036 +- 0.0022, r = 0.6 f0 = 0.04 1.0000 +- 0.0028, r = 0.05 0.995 +-
// 0.012).
constexpr int kSweepSize = 32;
constexpr double kMaxSigma = kFurnaceTolerance / 3.0; // the 1% bound is at least a 3-sigma test
constexpr double kUnbiasedSigmas = 4.0;

struct SweepMaterial {
    const char* label;
    const char* brdf;
    float roughness;
    glm::vec3 color;
    float anisotropy = 0.0f;
};
// The issue-16 plugins follow GGX; `measured` renders the shipped example table (glossy r = 0.5).
const SweepMaterial kSweepMaterials[] = {
    {"lambert", "lambert", 0.5f, {0.8f, 0.5f, 0.2f}},
    {"ggx r=0.05", "ggx", 0.05f, glm::vec3(1.0f)},
    {"ggx r=0.3", "ggx", 0.3f, {0.9f, 0.6f, 0.3f}},
    {"ggx r=1", "ggx", 1.0f, glm::vec3(1.0f)},
    {"ggx r=0.6 f0=0.04", "ggx", 0.6f, glm::vec3(0.04f)},
    {"glossy r=0.3", "glossy", 0.3f, {0.9f, 0.6f, 0.3f}},
    {"phong r=0.3", "phong", 0.3f, {0.9f, 0.6f, 0.3f}},
    {"blinn r=0.3", "blinn", 0.3f, {0.9f, 0.6f, 0.3f}},
    {"ward r=0.3", "ward", 0.3f, {0.9f, 0.6f, 0.3f}},
    {"ward r=0.4 a=0.9", "ward", 0.4f, glm::vec3(1.0f), 0.9f},
    {"measured example", "measured", 0.5f, glm::vec3(1.0f)},
};
enum { kLambert, kGgxMirrorish, kGgx03, kGgxRough, kGgxDielectric, kGlossy, kPhong, kBlinn, kWard,
       kWardAniso, kMeasured };

// The shipped example measured table, loaded once.
std::shared_ptr<const plugins::BrdfTable> exampleTable() {
    static const std::shared_ptr<const plugins::BrdfTable> kTable = [] {
        auto t = plugins::loadMerlBrdf(std::string(WAVELIT_RESOURCE_DIR) + "/brdfs/glossy-copper-r05.binary");
        EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message());
        return t.ok() ? *t : nullptr;
    }();
    return kTable;
}

plugins::BrdfParams paramsOf(const SweepMaterial& m) {
    return plugins::BrdfParams(m.color, m.roughness, m.anisotropy,
                               std::string(m.brdf) == "measured" ? exampleTable() : nullptr);
}

enum class Bound { OnePercent, Unbiased };

struct SweepCase {
    render::SamplerKind kind;
    int material;
    int passes;
    Bound bound;
};

std::string sweepName(const ::testing::TestParamInfo<SweepCase>& info) {
    std::string name = std::string(render::samplerKindName(info.param.kind)) + "_" +
                       kSweepMaterials[info.param.material].label;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

// Expected sphere pixels: L x E(mu) averaged over each pixel's footprint (E = rho for Lambert).
// Tabulating E costs ~1M BRDF evaluations, so each material's table is built once. An
// anisotropic lobe's E also depends on the view's azimuth in the shading frame (the tangent the
// tracers build from the normal: util::Frame), so there each sub-pixel's own view is integrated
// (32 x 32 cells: ~1e-4 relative for these lobes, far below the 1% bound), once per material.
std::vector<glm::dvec3> expectedSphere(const Furnace& f, const SweepMaterial& m, glm::vec3 env,
                                       const std::vector<PixelKind>& kinds) {
    static std::map<int, AlbedoTable> tables;
    static std::map<int, std::vector<glm::dvec3>> anisotropic; // the same furnace for every kind
    const int key = int(&m - kSweepMaterials);
    if (m.anisotropy > 0.0f)
        if (auto done = anisotropic.find(key); done != anisotropic.end()) return done->second;
    const plugins::BrdfParams params = paramsOf(m);
    auto it = tables.find(key);
    if (it == tables.end() && m.anisotropy == 0.0f)
        it = tables.emplace(key, AlbedoTable(*plugins::findBrdf(m.brdf), params)).first;
    const bool lambert = std::string(m.brdf) == "lambert";
    render::CpuCamera cam(f.scene->camera, f.size, f.size);
    std::vector<glm::dvec3> expected(kinds.size(), glm::dvec3(0.0));
    for (int y = 0; y < f.size; ++y)
        for (int x = 0; x < f.size; ++x) {
            const size_t i = size_t(y * f.size + x);
            if (kinds[i] != PixelKind::Sphere) continue;
            if (lambert) {
                expected[i] = glm::dvec3(m.color) * glm::dvec3(env);
                continue;
            }
            for (int a = 0; a < kSubpixels; ++a)
                for (int b = 0; b < kSubpixels; ++b) {
                    render::SurfacePoint sp;
                    const float u = (a + 0.5f) / kSubpixels, v = (b + 0.5f) / kSubpixels;
                    if (!f.hits(cam, x, y, u, v, &sp)) continue; // classify() said all hit
                    const glm::vec3 view = -cam.direction(x, y, u, v);
                    if (m.anisotropy > 0.0f)
                        expected[i] += plugins::directionalAlbedo(
                            *plugins::findBrdf(m.brdf), params,
                            util::Frame::fromNormal(sp.shading).toLocal(view), 32, 32);
                    else
                        expected[i] += it->second(glm::dot(view, sp.shading));
                }
            expected[i] *= glm::dvec3(env) / double(kSubpixels * kSubpixels);
        }
    if (m.anisotropy > 0.0f) anisotropic[key] = expected;
    return expected;
}

class SamplerFurnace : public ::testing::TestWithParam<SweepCase> {};

TEST_P(SamplerFurnace, SphereTotalIsEnvironmentTimesAlbedo) {
    const SweepCase c = GetParam();
    const SweepMaterial& sm = kSweepMaterials[c.material];
    scene::Material m;
    m.brdf = sm.brdf;
    m.roughness = sm.roughness;
    m.baseColor = sm.color;
    m.anisotropy = sm.anisotropy;
    m.brdfTable = paramsOf(sm).table;
    const glm::vec3 env(1.0f, 0.5f, 2.0f);
    Furnace f(m, env, kSweepSize);
    f.options.sampler = c.kind;
    auto tracer = render::CpuPathTracer::create(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    const std::vector<PixelKind> kinds = f.classify();
    const std::vector<glm::dvec3> expected = expectedSphere(f, sm, env, kinds);
    glm::dvec3 expectedSum(0.0);
    for (const glm::dvec3& e : expected) expectedSum += e;

    // Per-pass sphere sums, recovered from the running mean image (k x mean_k - previous: float
    // rounding of the mean costs ~1e-7 x k relative, far below the noise).
    glm::dvec3 sum(0.0), sum2(0.0), previous(0.0);
    for (int pass = 1; pass <= c.passes; ++pass) {
        ASSERT_TRUE((*tracer)->renderPass().ok());
        auto img = (*tracer)->image();
        ASSERT_TRUE(img.ok());
        glm::dvec3 total(0.0);
        for (size_t i = 0; i < kinds.size(); ++i)
            if (kinds[i] == PixelKind::Sphere) total += glm::dvec3(img->pixels[i]);
        total *= double(pass);
        const glm::dvec3 thisPass = total - previous;
        previous = total;
        sum += thisPass;
        sum2 += thisPass * thisPass;
    }
    auto img = (*tracer)->image();
    expectFinite(*img);
    const double n = double(c.passes);
    for (int ch = 0; ch < 3; ++ch) {
        const double mean = sum[ch] / n;
        const double var = c.passes > 1 ? std::max(0.0, sum2[ch] / n - mean * mean) * n / (n - 1)
                                        : 0.0;
        const double ratio = mean / expectedSum[ch];
        const double sigma = std::sqrt(var / n) / expectedSum[ch];
        // Passes for sigma = kMaxSigma: what a case would need (the table's source).
        const double needed = var / (expectedSum[ch] * expectedSum[ch] * kMaxSigma * kMaxSigma);
        std::printf("[furnace] %-8s %-18s ch %d: rendered/expected = %.5f, sigma %.5f (%d passes,"
                    " %.0f for sigma %.4f)%s\n",
                    render::samplerKindName(c.kind), sm.label, ch, ratio, sigma, c.passes, needed,
                    kMaxSigma, c.bound == Bound::Unbiased ? " [1% out of reach: 4 sigma]" : "");
        if (c.bound == Bound::OnePercent) {
            EXPECT_NEAR(ratio, 1.0, kFurnaceTolerance) << "channel " << ch;
            EXPECT_LE(sigma, kMaxSigma) << "channel " << ch << ": too few passes for the 1% bound";
        } else {
            EXPECT_NEAR(ratio, 1.0, kUnbiasedSigmas * sigma) << "channel " << ch;
        }
    }
}

// Passes per case: measured per-pass spreads at 32x32 (the "needed" column the test prints) with
// 30-60% margin (a spread estimated from few passes is itself uncertain); 1 where the sampler is
// exact in a constant environment (bsdf and cosine on Lambert: f cos / pdf = rho; bsdf on GGX
// with F0 = 1 and a narrow lobe: f cos / pdf = G1 ~ 1).
const SweepCase kSweep[] = {
    {render::SamplerKind::Uniform, kLambert, 130, Bound::OnePercent},
    {render::SamplerKind::Uniform, kGgx03, 256, Bound::Unbiased},
    {render::SamplerKind::Uniform, kGgxRough, 90, Bound::OnePercent},
    {render::SamplerKind::Uniform, kGgxDielectric, 1100, Bound::OnePercent},
    {render::SamplerKind::Cosine, kLambert, 1, Bound::OnePercent},
    {render::SamplerKind::Cosine, kGgx03, 256, Bound::Unbiased},
    {render::SamplerKind::Cosine, kGgxRough, 20, Bound::OnePercent},
    {render::SamplerKind::Cosine, kGgxDielectric, 2500, Bound::OnePercent},
    {render::SamplerKind::Bsdf, kLambert, 1, Bound::OnePercent},
    {render::SamplerKind::Bsdf, kGgxMirrorish, 1, Bound::OnePercent},
    // 8-11 needed with the Sobol' passes (docs/estimator.md "Random numbers").
    {render::SamplerKind::Bsdf, kGgx03, 14, Bound::OnePercent},
    {render::SamplerKind::Bsdf, kGgxRough, 360, Bound::OnePercent},
    {render::SamplerKind::Bsdf, kGgxDielectric, 90, Bound::OnePercent},
    {render::SamplerKind::Env, kLambert, 600, Bound::OnePercent},
    {render::SamplerKind::Env, kGgx03, 256, Bound::Unbiased},
    {render::SamplerKind::Env, kGgxRough, 500, Bound::OnePercent},
    {render::SamplerKind::Env, kGgxDielectric, 3400, Bound::OnePercent},
    {render::SamplerKind::Mis, kLambert, 120, Bound::OnePercent},
    {render::SamplerKind::Mis, kGgxMirrorish, 170, Bound::OnePercent},
    {render::SamplerKind::Mis, kGgx03, 130, Bound::OnePercent},
    {render::SamplerKind::Mis, kGgxRough, 430, Bound::OnePercent},
    // mis needs more passes since its env shadow ray's Russian roulette (docs/estimator.md): the
    // dielectric's weak lobe is where the roulette fires most (747 needed, was ~230).
    {render::SamplerKind::Mis, kGgxDielectric, 1100, Bound::OnePercent},
    // Lambert is EnvMis under every env since round 5 (docs/performance.md): `mis`'s estimator
    // with the same random numbers, so `mis`'s count (12 passes measured 24 needed).
    {render::SamplerKind::Wavelet, kLambert, 120, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kGgxMirrorish, 32, Bound::OnePercent},
    // 13-17 needed since round 4 (EnvMis here, `mis`'s roulette): the margin above.
    {render::SamplerKind::Wavelet, kGgx03, 40, Bound::OnePercent},
    // ggx r = 1 and r = 0.6 form products here: a constant env keeps the env-wider threshold of 16
    // (kUniformEnvMisSolidAngleRatio; `mis`'s technique would need ~1100 passes at r = 0.6).
    // Needed 42 and 38 with the tracers' 16^2 product (ProductBuild::Tracer, which the CPU tracer
    // builds since issue 12's last round), 39 and 35 with the paper's 32^2 one before it.
    {render::SamplerKind::Wavelet, kGgxRough, 60, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kGgxDielectric, 56, Bound::OnePercent},
    // 2.5-3 s per pass: two materials only (see above).
    {render::SamplerKind::Oracle, kLambert, 4, Bound::OnePercent},
    {render::SamplerKind::Oracle, kGgx03, 6, Bound::OnePercent},
    // Issue 16's plugins: bsdf (each plugin's own sampling), mis and wavelet on every one; passes
    // from the needed counts measured 2026-12-02 (in brackets) with the margin above. `measured`
    // is cosine-sampled (docs/brdfs.md): bsdf on its glossy example would need ~950 passes for 1%
    // and checks unbiasedness at 4 sigma; mis (~18 ms a pass) takes the 1% bound; wavelet (48
    // passes, but ~1 s a pass on the loaded 2-core machine: a whole-sphere product per hit) is
    // checked at 4 sigma.
    {render::SamplerKind::Bsdf, kGlossy, 16, Bound::OnePercent},     // [5-8]
    {render::SamplerKind::Bsdf, kPhong, 4, Bound::OnePercent},       // [1]
    {render::SamplerKind::Bsdf, kBlinn, 12, Bound::OnePercent},      // [5]
    {render::SamplerKind::Bsdf, kWard, 12, Bound::OnePercent},       // [4]
    {render::SamplerKind::Bsdf, kWardAniso, 28, Bound::OnePercent},  // [18]
    {render::SamplerKind::Bsdf, kMeasured, 64, Bound::Unbiased},     // [952]
    {render::SamplerKind::Mis, kGlossy, 44, Bound::OnePercent},      // [20; 28 with roulette]
    {render::SamplerKind::Mis, kPhong, 8, Bound::OnePercent},        // [3]
    {render::SamplerKind::Mis, kBlinn, 24, Bound::OnePercent},       // [8-15]
    {render::SamplerKind::Mis, kWard, 24, Bound::OnePercent},        // [8-15]
    {render::SamplerKind::Mis, kWardAniso, 48, Bound::OnePercent},   // [33]
    {render::SamplerKind::Mis, kMeasured, 900, Bound::OnePercent},   // [457; 608 with roulette]
    // Under the furnace's constant env these lobes are EnvMis (docs/performance.md "Wavelet pass
    // cost, round 3"), whose vertices are now `mis`'s technique with its shadow-ray roulette
    // (round 4): the same estimator as `mis`, so `mis`'s counts (needed at 10/4/6/6 passes:
    // glossy 14, phong 9, blinn 8, ward 8, where 6/2/3/3 sufficed before the roulette; phong
    // read 28 at 14 passes).
    {render::SamplerKind::Wavelet, kGlossy, 44, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kPhong, 44, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kBlinn, 24, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kWard, 24, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kWardAniso, 48, Bound::OnePercent}, // [21 before]
    {render::SamplerKind::Wavelet, kMeasured, 16, Bound::Unbiased},    // [48]; 72: 1.0005 +- 0.0029
};

INSTANTIATE_TEST_SUITE_P(EverySampler, SamplerFurnace, ::testing::ValuesIn(kSweep), sweepName);

TEST(SamplerFurnaceTable, EverySamplerKindHasALambertAndAGgxCaseAtOnePercent) {
    for (render::SamplerKind kind : render::allSamplerKinds()) {
        bool lambert = false, ggx = false;
        for (const SweepCase& c : kSweep)
            if (c.kind == kind && c.bound == Bound::OnePercent) {
                lambert |= c.material == kLambert;
                ggx |= c.material != kLambert;
            }
        EXPECT_TRUE(lambert) << render::samplerKindName(kind);
        EXPECT_TRUE(ggx) << render::samplerKindName(kind);
    }
}

} // namespace
} // namespace wavelit
