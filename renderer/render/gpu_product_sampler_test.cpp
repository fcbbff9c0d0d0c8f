// The Vulkan `wavelet` and `oracle` samplers (shaders/common/direction_sampler.glsl) judged on
// their own: their per-hit products are built differently from the CPU's (wavelet: dense at the
// cell centres; oracle: a coarser dense grid, see the GLSL), so the twin test cannot cover them.
// For the six shading configurations of direction_sampler_test (grazing 85 degrees, mirror-like
// r = 0.02, Lambert, ...) under the studio env and a sky with a 10^6 sun, the GPU draws 40k
// directions per configuration and reports what its mixture was built from (weights, window,
// product pyramid). The pdf those pieces define is evaluated on the CPU (the env tables are the
// same object the GPU got; the BSDF is the C++ twin of the GLSL plugin); then:
//  - chi-square of the GPU's directions against that pdf (p > Sidak-corrected 0.01);
//  - the pdf the GPU returned with each direction equals that pdf at the direction (exactness of
//    the estimator's division, DESIGN.md §4);
//  - the pdf integrates to 1 (minus the BSDF's invalid mass);
//  - oracle only: the GPU's window is the CPU's chooseWindow for the exact axis, and its leaf
//    masses are the dense product the CPU tabulates over that window (brute force).
#include "render/direction_sampler.h"
#include "render/gpu_path_tracer.h"
#include "render/gpu_sampler_data.h"
#include "render/oracle_sampler.h"
#include "render/sampler_chi_square.h"
#include "render/sampler_test_configs.h"
#include "render/sampler_test_envs.h"
#include "util/hemisphere_sampling.h"
#include "util/image.h"
#include "vk/buffer.h"
#include "vk/command_runner.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

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
// The shader's gMass: levels 0..4 (wavelet), 0..5 (oracle).
int pyramidFloats(SamplerKind kind) {
    const int m = kind == SamplerKind::Oracle ? kGpuOracleLevel : kGpuMaxProductLevel;
    return ((1 << (2 * (m + 1))) - 1) / 3;
}
int infoFloats(SamplerKind kind) { return 8 + pyramidFloats(kind); }
const double kChiAlpha = util::sidakAlpha(0.01, 4 * kConfigs);

// Inputs per configuration: t, b, n, wo (world; w of n = BRDF type, w of wo = roughness) and the
// base colour. Outputs per sample: (wi, pdf); per configuration (from its sample 0): weights
// (product, bsdf, env), window (k, ox, oy, m) and the product pyramid's masses.
std::string kernelSource(SamplerKind kind) {
    const bool oracle = kind == SamplerKind::Oracle;
    return std::string(R"(#version 460
#extension GL_GOOGLE_include_directive : require
)") + (oracle ? "#define WAVELIT_ORACLE_SAMPLER 1\n" : "") + R"(
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
layout(local_size_x = 64) in;
struct EnvNode { float py0, px0y0, px0y1; int firstChild; };
struct SamplerMaterial { uint mode, tableOffset, nodeOffset, scalingOffset; float mixBsdf, capHalfAngle; uint aroundNormal, refineMaxLevels; float refineCellAngle; uint pad0, pad1, pad2; };
layout(std430, binding = 0) readonly buffer EnvTable { EnvNode envNodes[]; };
layout(std430, binding = 1) readonly buffer SamplerMaterials { SamplerMaterial samplerMaterials[]; };
layout(std430, binding = 2) readonly buffer SamplerWords { uint samplerWords[]; };
layout(std430, binding = 3) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 4) buffer Samples { vec4 samples[]; };
layout(std430, binding = 5) buffer Info { float info[]; };
layout(push_constant) uniform Push { uint samplesPerConfig, configs, tailOffset, lit; float envMean, cosYaw, sinYaw; int envLevel; } pc;
#include "common/direction_sampler.glsl"
#include "common/rng.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.samplesPerConfig * pc.configs) return;
    uint c = i / pc.samplesPerConfig;
    vec4 t = inputs[5u * c], b = inputs[5u * c + 1u], n = inputs[5u * c + 2u], wo = inputs[5u * c + 3u];
    vec3 color = inputs[5u * c + 4u].rgb;
    Frame f;
    f.t = t.xyz;
    f.b = b.xyz;
    f.n = n.xyz;
    SamplerGlobals g;
    g.kind = )" + (oracle ? "kSamplerOracle" : "kSamplerWavelet") + R"(;
    g.lit = pc.lit != 0u;
    g.tailOffset = pc.tailOffset;
    g.envMean = pc.envMean;
    g.envLevel = pc.envLevel;
    g.cosSinYaw = vec2(pc.cosYaw, pc.sinYaw);
    DirSampler s = dsSetup(g, samplerMaterials[c], f, frameToLocal(f, wo.xyz), uint(n.w), color, wo.w);
    Pcg32 rng = pcgSeed(uint64_t(7919u + c), uint64_t(i));
    float u1 = pcgFloat(rng);
    float u2 = pcgFloat(rng);
    float u3 = pcgFloat(rng);
    vec3 wi;
    float pdf;
    bool valid = dsSample(s, u1, u2, u3, wi, pdf);
    samples[i] = valid ? vec4(wi, pdf) : vec4(0.0, 0.0, 0.0, -1.0);
    if (i % pc.samplesPerConfig == 0u) {
        uint base = c * uint()" + std::to_string(infoFloats(kind)) + R"();
        info[base] = s.cProduct;
        info[base + 1u] = s.cBsdf;
        info[base + 2u] = s.cEnv;
        info[base + 3u] = float(s.k);
        info[base + 4u] = float(s.ox);
        info[base + 5u] = float(s.oy);
        info[base + 6u] = float(s.m);
        info[base + 7u] = float(s.refineLevels);
        for (int k = 0; k < )" + std::to_string(pyramidFloats(kind)) + R"(; ++k) info[base + 8u + uint(k)] = gMass[k];
    }
}
)";
}

// What the GPU built for one configuration, and the pdf it defines (dsMixturePdf's CPU form).
struct GpuMixture {
    double cProduct = 0, cBsdf = 0, cEnv = 0;
    int k = 0, ox = 0, oy = 0, m = 0, refineLevels = 0;
    std::vector<double> mass; // the pyramid, levels 0..m
    const SamplerEnvironment* env = nullptr;
    const SamplerMaterial* material = nullptr;
    ShadingPoint point;

    double productPdf(glm::dvec2 p) const {
        const int level = k + m, shift = m - 1, side = 1 << m;
        const double scale = std::ldexp(1.0, level);
        const int gx = int(p.x * scale), gy = int(p.y * scale);
        const int lx = gx - (ox << shift), ly = gy - (oy << shift);
        if (lx < 0 || ly < 0 || lx >= side || ly >= side)
            return 0.0;
        double probability = 1.0;
        int x = 0, y = 0;
        for (int l = 0; l < m; ++l) {
            const int s = 1 << (l + 1), off = ((1 << (2 * (l + 1))) - 1) / 3;
            const int c0 = off + 2 * y * s + 2 * x, c1 = c0 + s;
            const double a = mass[size_t(c0)], b = mass[size_t(c0) + 1], c = mass[size_t(c1)],
                         d = mass[size_t(c1) + 1];
            const int cx = (lx >> (m - 1 - l)) & 1, cy = (ly >> (m - 1 - l)) & 1;
            const double row = cy == 0 ? a + b : c + d;
            const double column = cy == 0 ? (cx == 0 ? a : b) : (cx == 0 ? c : d);
            probability *= (a + b + c + d > 0 ? row / (a + b + c + d) : 0.5) *
                           (row > 0 ? column / row : 0.5);
            x = 2 * x + cx;
            y = 2 * y + cy;
        }
        int l = level, x2 = gx, y2 = gy;
        for (int r = 0; r < refineLevels; ++r) {
            double w[4];
            refineWeights(l, x2, y2, w);
            const double scale2 = std::ldexp(1.0, l + 1);
            const int cx = std::clamp(int(p.x * scale2) - 2 * x2, 0, 1);
            const int cy = std::clamp(int(p.y * scale2) - 2 * y2, 0, 1);
            const double row = cy == 0 ? w[0] + w[1] : w[2] + w[3];
            probability *= share(row, w[0] + w[1] + w[2] + w[3]) * share(w[2 * cy + cx], row);
            ++l;
            x2 = 2 * x2 + cx;
            y2 = 2 * y2 + cy;
        }
        return probability * env->fine().pdfWithin({l, x2, y2}, p);
    }

    static double share(double part, double whole) { return whole > 0 ? part / whole : 0.5; }

    // dsRefineWeights: the env table's split of the cell times BRDF x cos at the children's
    // centres, plus 2% of the largest.
    void refineWeights(int l, int x, int y, double w[4]) const {
        const auto& table = env->fine().table();
        int node = 0, reached = 0;
        while (reached < l && table[size_t(node)].firstChild >= 0) {
            const int shift = l - reached - 1;
            node = table[size_t(node)].firstChild + (((x >> shift) & 1) | (((y >> shift) & 1) << 1));
            ++reached;
        }
        for (int c = 0; c < 4; ++c)
            w[c] = 1.0;
        if (reached == l && table[size_t(node)].firstChild >= 0) {
            auto split = [](float s, double& p0, double& p1) {
                if (std::signbit(s)) {
                    p1 = -double(s);
                    p0 = 1.0 - p1;
                } else {
                    p0 = double(s);
                    p1 = 1.0 - p0;
                }
            };
            double py0, py1, pl0, pr0, pl1, pr1;
            split(table[size_t(node)].py0, py0, py1);
            split(table[size_t(node)].px0y0, pl0, pr0);
            split(table[size_t(node)].px0y1, pl1, pr1);
            w[0] = py0 * pl0;
            w[1] = py0 * pr0;
            w[2] = py1 * pl1;
            w[3] = py1 * pr1;
        }
        const double side = std::ldexp(1.0, -(l + 1));
        double h[4], hmax = 0.0;
        for (int c = 0; c < 4; ++c) {
            const glm::dvec2 centre((2 * x + (c & 1) + 0.5) * side, (2 * y + (c >> 1) + 0.5) * side);
            const glm::vec3 d = glm::vec3(env->toWorld(env->map().toDirection(0, centre)));
            h[c] = brdfCos(d);
            hmax = std::max(hmax, h[c]);
        }
        if (hmax > 0.0 && std::isfinite(hmax))
            for (int c = 0; c < 4; ++c)
                w[c] *= h[c] + 0.02 * hmax;
    }

    double brdfCos(const glm::vec3& wi) const {
        const glm::vec3 local(glm::dot(wi, point.t), glm::dot(wi, point.b), glm::dot(wi, point.n));
        const glm::vec3 woLocal(glm::dot(point.wo, point.t), glm::dot(point.wo, point.b),
                                glm::dot(point.wo, point.n));
        if (local.z <= 0.0f)
            return 0.0;
        return double(util::luminance(material->brdf->eval(material->params, woLocal, local) * local.z));
    }

    double pdf(const glm::vec3& wi) const {
        const glm::vec3 local(glm::dot(wi, point.t), glm::dot(wi, point.b), glm::dot(wi, point.n));
        const glm::vec3 woLocal(glm::dot(point.wo, point.t), glm::dot(point.wo, point.b),
                                glm::dot(point.wo, point.n));
        const glm::dvec2 p = octSquarePoint(env->map(), env->toLocal(glm::dvec3(wi)));
        double v = cBsdf * material->brdf->pdf(material->params, woLocal, local);
        v += cEnv * env->pdfLocal(env->toLocal(glm::dvec3(wi)));
        if (cProduct > 0)
            v += cProduct * productPdf(p) / (4.0 * util::kPi);
        return v;
    }
};

// Oracle only: the GPU chose the window the CPU's chooseWindow picks for the exact axis, and its
// leaves are the dense product (env-weighted BRDF x cos times the env's averages) the CPU
// tabulates by brute force over that window.
void expectOracleLeavesMatchTheCpu(const GpuMixture& mix) {
    const SamplerEnvironment& env = *mix.env;
    const bool lambert = std::string(mix.material->brdf->name()) == "lambert";
    const glm::vec3 axisWorld = lambert ? mix.point.n : reflectionOf(mix.point);
    const glm::dvec3 axis = env.toLocal(glm::normalize(glm::dvec3(axisWorld)));
    const double cap = oracleCapHalfAngle(lambert, mix.material->params.roughness);
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

struct Case {
    SamplerKind kind;
    int env; // 0: studio, 1: sun
};

class GpuProductSampler : public ::testing::TestWithParam<Case> {};

TEST_P(GpuProductSampler, ChiSquareAndExactPdfForEveryConfiguration) {
    const SamplerKind kind = GetParam().kind;
    const bool studio = GetParam().env == 0;
    const int kInfoFloats = infoFloats(kind), kPyramid = pyramidFloats(kind);
    scene::Environment envSource;
    std::vector<SamplerMaterial> materials;
    for (const Config& c : kConfigList)
        materials.push_back({c.name, plugins::findBrdf(c.brdf), {glm::vec3(0.9f, 0.8f, 0.7f), c.roughness}});
    if (studio) {
        auto studioEnv = loadDownsampledEnvironment(
            std::string(WAVELIT_RESOURCE_DIR) + "/envmaps/studio.exr", 256);
        ASSERT_TRUE(studioEnv.ok());
        envSource = *studioEnv;
        envSource.rotationDeg = 30.0f;
    } else {
        const ShadingPoint glossy = shadingPoint(kConfigList[3], 3);
        const glm::vec3 r = reflectionOf(glossy);
        envSource = makeSunSkyEnvironment(256, glm::normalize(r + glm::vec3(0.0f, 0.14f, 0.0f)), 1e6);
    }
    SceneSamplerTables scene;
    scene.tables = DirectionSamplerTables::build(envSource, materials, kind);
    for (int c = 0; c < kConfigs; ++c)
        scene.samplerIndexOfMaterial.push_back(c);
    auto packed = packGpuSamplers(scene, kind, kConfigs);
    ASSERT_TRUE(packed.ok()) << packed.error().message();
    const SamplerEnvironment& env = scene.tables->environment();

    std::vector<float> in;
    for (int c = 0; c < kConfigs; ++c) {
        const ShadingPoint p = shadingPoint(kConfigList[c], size_t(c));
        const bool ggx = std::string(kConfigList[c].brdf) == "ggx";
        const float v[20] = {p.t.x, p.t.y, p.t.z, 0, p.b.x, p.b.y, p.b.z, 0,
                             p.n.x, p.n.y, p.n.z, ggx ? 1.0f : 0.0f,
                             p.wo.x, p.wo.y, p.wo.z, kConfigList[c].roughness,
                             0.9f, 0.8f, 0.7f, 0};
        in.insert(in.end(), v, v + 20);
    }
    auto ctx = vk::Context::create({"", true});
    ASSERT_TRUE(ctx.ok()) << ctx.error().message();
    ASSERT_TRUE((*ctx)->hasFloat64());
    auto spirv = vk::compileComputeShader(kernelSource(kind), "product_sampler_test.comp",
                                          {{gpuShaderDirectory(), gpuPluginDirectory()}, {}});
    ASSERT_TRUE(spirv.ok()) << spirv.error().message();
    const uint32_t total = uint32_t(kSamples * kConfigs);
    std::vector<float> samples(size_t(total) * 4), info(size_t(kConfigs) * kInfoFloats);
    {
        using vk::BindingKind;
        auto kernel = vk::ComputeKernel::create(
            **ctx, {"wavelet sampler test", *spirv, std::vector<BindingKind>(6, BindingKind::StorageBuffer), 32});
        ASSERT_TRUE(kernel.ok()) << kernel.error().message();
        const GpuSamplerData& d = *packed;
        struct Blob {
            const void* data;
            size_t bytes;
        } blobs[] = {{d.envNodes.data(), d.envNodes.size() * 16},
                     {d.materials.data(), d.materials.size() * sizeof(GpuSamplerMaterial)},
                     {d.words.data(), d.words.size() * 4},
                     {in.data(), in.size() * 4},
                     {nullptr, samples.size() * 4},
                     {nullptr, info.size() * 4}};
        std::vector<vk::Buffer> buffers;
        for (uint32_t i = 0; i < 6; ++i) {
            auto b = vk::Buffer::create(**ctx, blobs[i].bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "b");
            ASSERT_TRUE(b.ok());
            if (blobs[i].data)
                b->write(blobs[i].data, blobs[i].bytes);
            buffers.push_back(std::move(b.value()));
            kernel->bind(i, buffers.back());
        }
        struct {
            uint32_t samplesPerConfig, configs, tailOffset, lit;
            float envMean, cosYaw, sinYaw;
            int32_t envLevel;
        } push{uint32_t(kSamples), uint32_t(kConfigs), d.tailOffset, d.lit ? 1u : 0u, d.envMean,
               float(std::cos(float(envSource.rotationDeg * util::kPi / 180.0f))),
               float(std::sin(float(envSource.rotationDeg * util::kPi / 180.0f))),
               int32_t(d.envLevel)};
        auto runner = vk::CommandRunner::create(**ctx, "wavelet sampler test");
        ASSERT_TRUE(runner.ok());
        ASSERT_TRUE((*runner)
                        ->run([&](VkCommandBuffer cmd) {
                            kernel->dispatch(cmd, (total + 63) / 64, 1, 1, &push);
                            vk::computeToComputeAndHostBarrier(cmd);
                        })
                        .ok());
        buffers[4].read(samples.data(), samples.size() * 4);
        buffers[5].read(info.data(), info.size() * 4);
    }
    EXPECT_EQ((*ctx)->validationMessageCount(), 0);

    for (int c = 0; c < kConfigs; ++c) {
        SCOPED_TRACE(std::string(samplerKindName(kind)) + (studio ? " studio " : " sun ") +
                     kConfigList[c].name);
        const float* f = &info[size_t(c) * kInfoFloats];
        GpuMixture mix;
        mix.cProduct = f[0];
        mix.cBsdf = f[1];
        mix.cEnv = f[2];
        mix.k = int(f[3]);
        mix.ox = int(f[4]);
        mix.oy = int(f[5]);
        mix.m = int(f[6]);
        mix.refineLevels = int(f[7]);
        mix.mass.assign(f + 8, f + 8 + kPyramid);
        mix.env = &env;
        mix.material = &materials[size_t(c)];
        mix.point = shadingPoint(kConfigList[c], size_t(c));
        EXPECT_NEAR(mix.cProduct + mix.cBsdf + mix.cEnv, 1.0, 1e-6);
        if (kind == SamplerKind::Oracle) {
            EXPECT_GT(mix.cProduct, 0.1); // the dense product is always in the mixture
            expectOracleLeavesMatchTheCpu(mix);
        }

        // The GPU's pdf with each draw is the mixture's pdf at the draw.
        int next = 0, mismatches = 0;
        for (int i = 0; i < kSamples; ++i) {
            const float* s = &samples[(size_t(c) * kSamples + size_t(i)) * 4];
            if (s[3] < 0.0f)
                continue;
            const double expected = mix.pdf(glm::vec3(s[0], s[1], s[2]));
            if (std::abs(s[3] - expected) > 1e-3 * expected)
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
        o.toBinFrame = [&](const glm::dvec3& d) { return env.toLocal(d); };
        o.fromBinFrame = [&](const glm::dvec3& d) { return env.toWorld(d); };
        const auto result = sphereChiSquare(
            [&](float, float, float) -> std::optional<glm::vec3> {
                const float* s = &samples[(size_t(c) * kSamples + size_t(next++)) * 4];
                if (s[3] < 0.0f)
                    return std::nullopt;
                return glm::vec3(s[0], s[1], s[2]);
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
                                           Case{SamplerKind::Oracle, 0}, Case{SamplerKind::Oracle, 1}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                             return std::string(i.param.kind == SamplerKind::Oracle ? "Oracle" : "Wavelet") +
                                    (i.param.env == 0 ? "Studio" : "Sun");
                         });

} // namespace
} // namespace wavelit::render
