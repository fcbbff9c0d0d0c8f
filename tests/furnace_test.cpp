// White furnace (issue 6 acceptance, issue 3's closed-form case): a sphere in a constant
// environment L, rendered with bounces = 1 by the CPU reference tracer. A convex object sees
// only the environment, so the pixel value is L × the directional albedo E(μo) of its BRDF at
// the pixel's view angle: exactly ρL for Lambert, and for GGX the E(μo) that dense quadrature of
// the C++ BRDF gives (plugins/brdf_albedo.h) — independent of the sampling code under test.
// Background pixels see L exactly; no pixel may be NaN or Inf.
#include "render/testing/cpu_analytic_scenes.h"
#include "render/reference/cpu_camera.h"
#include "render/reference/cpu_path_tracer.h"
#include "render/reference/cpu_surface.h"
#include "render/sampling/direction_sampler.h"
#include "render/session/integrator_factory.h"
#include "scene/bvh.h"

#include "plugins/brdf.h"
#include "plugins/testing/brdf_albedo.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace wavelit {
namespace {

// The acceptance bound: within 1% of the analytic value.
constexpr double kFurnaceTolerance = 0.01;
// Background pixels: float rounding of L × 1 only.
constexpr float kExactTolerance = 1e-6f;
constexpr int kSize = 64;
constexpr int kSubpixels = 4; // per axis, for the expected value of a pixel (view angle varies)

enum class PixelKind { Sphere, Background, Edge };

struct Furnace {
    std::shared_ptr<scene::Scene> scene;
    std::shared_ptr<const scene::Bvh> bvh;
    render::RenderOptions options;

    int size;

    Furnace(const scene::Material& material, glm::vec3 env, int imageSize = kSize)
        : size(imageSize) {
        scene = render::makeFurnaceScene(material, env);
        bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*scene));
        options.width = size;
        options.height = size;
        options.bounces = 1;
        options.seed = 3;
        options.device = render::DeviceChoice::Cpu;
    }

    bool hits(const render::CpuCamera& cam, int x, int y, float u, float v,
              render::SurfacePoint* sp = nullptr) const {
        glm::vec3 d = cam.direction(x, y, u, v);
        scene::BvhHit hit;
        if (!scene::intersect(*bvh, cam.origin(), d, 0.0f, std::numeric_limits<float>::max(), hit))
            return false;
        if (sp) *sp = render::surfaceAt(*bvh, hit, cam.origin(), d);
        return true;
    }

    // Pixels wholly on the sphere or wholly off it (corners and centre agree); the silhouette
    // mixes both and has no single expected value.
    std::vector<PixelKind> classify() const {
        render::CpuCamera cam(scene->camera, size, size);
        std::vector<PixelKind> kinds;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                int count = 0;
                for (glm::vec2 j : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1),
                                    glm::vec2(1, 1), glm::vec2(0.5f, 0.5f)})
                    count += hits(cam, x, y, j.x, j.y) ? 1 : 0;
                kinds.push_back(count == 5   ? PixelKind::Sphere
                                : count == 0 ? PixelKind::Background
                                             : PixelKind::Edge);
            }
        return kinds;
    }
};

// E(μ) of a BRDF tabulated by quadrature on s = sqrt(μ) (E changes fastest at grazing μ → 0),
// interpolated linearly.
class AlbedoTable {
public:
    AlbedoTable(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
        for (int i = 0; i <= kNodes; ++i) {
            double s = std::max(double(i) / kNodes, 1e-3);
            float mu = float(s * s);
            glm::vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            m_values.push_back(plugins::directionalAlbedo(brdf, params, wo, 128, 128));
        }
    }
    glm::dvec3 operator()(double mu) const {
        double s = std::sqrt(std::clamp(mu, 0.0, 1.0)) * kNodes;
        int i = std::min(int(s), kNodes - 1);
        double f = s - i;
        return m_values[i] * (1.0 - f) + m_values[i + 1] * f;
    }

private:
    static constexpr int kNodes = 64;
    std::vector<glm::dvec3> m_values;
};

void expectFinite(const util::ImageRGB& img) {
    for (const glm::vec3& p : img.pixels)
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(p[c]));
}

TEST(Furnace, LambertSphereIsAlbedoTimesEnvironmentEverywhere) {
    scene::Material m;
    m.brdf = "lambert";
    m.baseColor = glm::vec3(0.8f, 0.5f, 0.2f);
    const glm::vec3 env(1.0f, 0.5f, 2.0f);
    Furnace f(m, env);
    auto tracer = render::createCpuPathTracer(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    for (int pass = 0; pass < 8; ++pass) ASSERT_TRUE((*tracer)->renderPass().ok());
    auto img = (*tracer)->image();
    ASSERT_TRUE(img.ok());
    expectFinite(*img);

    auto kinds = f.classify();
    int sphere = 0, background = 0;
    double worst = 0.0;
    for (int i = 0; i < kSize * kSize; ++i) {
        const glm::vec3& p = img->pixels[i];
        if (kinds[i] == PixelKind::Background) {
            ++background;
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], env[c], kExactTolerance);
        } else if (kinds[i] == PixelKind::Sphere) {
            ++sphere;
            for (int c = 0; c < 3; ++c) {
                double expected = double(m.baseColor[c]) * env[c];
                worst = std::max(worst, std::abs(p[c] - expected) / expected);
                ASSERT_NEAR(p[c], expected, kFurnaceTolerance * expected) << i << " channel " << c;
            }
        }
    }
    std::printf("[furnace] lambert: %d sphere px, %d background px, worst rel. error %.2e\n",
                sphere, background, worst);
    EXPECT_GT(sphere, 1000);
    EXPECT_GT(background, 500);
}

TEST(Furnace, LambertSphereUnderSkyOverBlackGroundSeesHalfSpaceIrradiance) {
    // Env: upper hemisphere L, lower hemisphere black (a 2×2 equirect: row 0 is the top, v < ½
    // is d.y > 0). A cosine-weighted hemisphere around n has the fraction (1 + n.y)/2 of its
    // mass above the horizon, so the pixel value is ρ L (1 + n_s.y)/2: this checks the env's
    // orientation and the tracer's frames, not only a constant.
    scene::Material m;
    m.baseColor = glm::vec3(0.6f);
    Furnace f(m, glm::vec3(1.0f));
    auto sky = std::make_shared<util::ImageRGB>(2, 2, glm::vec3(0.0f));
    sky->at(0, 0) = sky->at(1, 0) = glm::vec3(2.0f);
    f.scene->lighting.environment.image = sky;
    auto tracer = render::CpuPathTracer::create(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    // Each sample is ρL × Bernoulli((1 + n.y)/2); the dimmer lower half (~750 pixels, p ≈ 0.3)
    // needs 256 passes for a relative standard error of ~0.35%, a third of the 1% bound.
    for (int pass = 0; pass < 256; ++pass) ASSERT_TRUE((*tracer)->renderPass().ok());
    auto img = (*tracer)->image();
    expectFinite(*img);

    render::CpuCamera cam(f.scene->camera, kSize, kSize);
    auto kinds = f.classify();
    double rendered[2] = {0, 0}, expected[2] = {0, 0}; // upper and lower half of the image
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (kinds[y * kSize + x] != PixelKind::Sphere) continue;
            double e = 0.0;
            for (int a = 0; a < kSubpixels; ++a)
                for (int b = 0; b < kSubpixels; ++b) {
                    render::SurfacePoint sp;
                    ASSERT_TRUE(f.hits(cam, x, y, (a + 0.5f) / kSubpixels, (b + 0.5f) / kSubpixels,
                                       &sp));
                    e += 0.6 * 2.0 * 0.5 * (1.0 + sp.shading.y);
                }
            int half = y < kSize / 2 ? 0 : 1;
            expected[half] += e / (kSubpixels * kSubpixels);
            rendered[half] += img->at(x, y).x;
        }
    for (int half = 0; half < 2; ++half) {
        EXPECT_NEAR(rendered[half] / expected[half], 1.0, kFurnaceTolerance) << "half " << half;
        std::printf("[furnace] sky over black, %s half: rendered/expected = %.5f\n",
                    half == 0 ? "upper" : "lower", rendered[half] / expected[half]);
    }
    EXPECT_GT(expected[0], 2.0 * expected[1]); // the sky side really is the bright side
}

struct GgxCase {
    float roughness;
    glm::vec3 f0;
};

class GgxFurnace : public ::testing::TestWithParam<GgxCase> {};

TEST_P(GgxFurnace, SphereIsEnvironmentTimesDirectionalAlbedo) {
    scene::Material m;
    m.brdf = "ggx";
    m.roughness = GetParam().roughness;
    m.baseColor = GetParam().f0;
    const glm::vec3 env(1.0f, 0.5f, 2.0f);
    Furnace f(m, env);
    auto tracer = render::CpuPathTracer::create(f.scene, f.bvh, f.options);
    ASSERT_TRUE(tracer.ok()) << tracer.error().message();
    const int passes = 64;
    for (int pass = 0; pass < passes; ++pass) ASSERT_TRUE((*tracer)->renderPass().ok());
    auto img = (*tracer)->image();
    ASSERT_TRUE(img.ok());
    expectFinite(*img);

    const AlbedoTable albedo(*plugins::findBrdf("ggx"), {m.baseColor, m.roughness});
    render::CpuCamera cam(f.scene->camera, kSize, kSize);
    auto kinds = f.classify();
    glm::dvec3 sumRendered(0.0), sumExpected(0.0);
    int sphere = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            int i = y * kSize + x;
            if (kinds[i] == PixelKind::Background) {
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(img->pixels[i][c], env[c], kExactTolerance);
                continue;
            }
            if (kinds[i] != PixelKind::Sphere) continue;
            ++sphere;
            // The pixel's expectation: E at the view angle averaged over its footprint.
            glm::dvec3 expected(0.0);
            for (int a = 0; a < kSubpixels; ++a)
                for (int b = 0; b < kSubpixels; ++b) {
                    render::SurfacePoint sp;
                    float u = (a + 0.5f) / kSubpixels, v = (b + 0.5f) / kSubpixels;
                    ASSERT_TRUE(f.hits(cam, x, y, u, v, &sp));
                    double mu = glm::dot(-cam.direction(x, y, u, v), sp.shading);
                    expected += albedo(mu);
                }
            expected *= glm::dvec3(env) / double(kSubpixels * kSubpixels);
            sumExpected += expected;
            sumRendered += glm::dvec3(img->pixels[i]);
        }
    EXPECT_GT(sphere, 1000);
    for (int c = 0; c < 3; ++c) {
        double ratio = sumRendered[c] / sumExpected[c];
        EXPECT_NEAR(ratio, 1.0, kFurnaceTolerance) << "channel " << c;
        std::printf("[furnace] ggx r=%.2f channel %d: rendered/expected = %.5f\n",
                    GetParam().roughness, c, ratio);
    }
}

INSTANTIATE_TEST_SUITE_P(Roughness, GgxFurnace,
                         ::testing::Values(GgxCase{0.05f, glm::vec3(1.0f)},
                                           GgxCase{0.3f, glm::vec3(0.9f, 0.6f, 0.3f)},
                                           GgxCase{1.0f, glm::vec3(1.0f)},
                                           GgxCase{0.6f, glm::vec3(0.04f)}));

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
};
const SweepMaterial kSweepMaterials[] = {
    {"lambert", "lambert", 0.5f, {0.8f, 0.5f, 0.2f}},
    {"ggx r=0.05", "ggx", 0.05f, glm::vec3(1.0f)},
    {"ggx r=0.3", "ggx", 0.3f, {0.9f, 0.6f, 0.3f}},
    {"ggx r=1", "ggx", 1.0f, glm::vec3(1.0f)},
    {"ggx r=0.6 f0=0.04", "ggx", 0.6f, glm::vec3(0.04f)},
};
enum { kLambert, kGgxMirrorish, kGgx03, kGgxRough, kGgxDielectric };

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
// Tabulating E costs ~1M BRDF evaluations, so each material's table is built once.
std::vector<glm::dvec3> expectedSphere(const Furnace& f, const SweepMaterial& m, glm::vec3 env,
                                       const std::vector<PixelKind>& kinds) {
    static std::map<int, AlbedoTable> tables;
    const int key = int(&m - kSweepMaterials);
    const plugins::BrdfParams params{m.color, m.roughness};
    auto it = tables.find(key);
    if (it == tables.end())
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
                    expected[i] += it->second(glm::dot(-cam.direction(x, y, u, v), sp.shading));
                }
            expected[i] *= glm::dvec3(env) / double(kSubpixels * kSubpixels);
        }
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
    {render::SamplerKind::Bsdf, kGgx03, 8, Bound::OnePercent},
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
    {render::SamplerKind::Mis, kGgxDielectric, 340, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kLambert, 12, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kGgxMirrorish, 32, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kGgx03, 16, Bound::OnePercent},
    // 18-26 needed since env NEE (issue 20): the NEE term and the BSDF continuation each vary.
    {render::SamplerKind::Wavelet, kGgxRough, 40, Bound::OnePercent},
    {render::SamplerKind::Wavelet, kGgxDielectric, 44, Bound::OnePercent},
    // 2.5-3 s per pass: two materials only (see above).
    {render::SamplerKind::Oracle, kLambert, 4, Bound::OnePercent},
    {render::SamplerKind::Oracle, kGgx03, 6, Bound::OnePercent},
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
