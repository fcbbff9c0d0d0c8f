// Deterministic variance study of the direction samplers (issue 6; architecture.md §4.1's study):
// one shading point (GGX, F0 0.9, view 45 degrees, normal +Y), no visibility, and for each
// sampler the EXACT per-sample variance of the estimator g/p, g = luminance(f L cos), computed on
// the environment's own texels (render/testing/sampler_integrals.h): Var = integral g^2/p - I^2.
// Environments: a synthetic sky with a 0.53-degree sun at 1e5 x the sky mean, 12 degrees from the
// reflection vector (1024 x 512), and the bundled city / courtyard maps box-filtered to 512 x 256.
// Prints markdown tables (relative variance Var / I^2 per sampler and roughness, the wavelet /
// oracle ratio — our efficiency figure — and mis / wavelet), plus table build and per-point
// construction times. docs/sampler-variance.md holds a run's output. Plain main: no timing is
// asserted anywhere (architecture.md §8).
// --brdfs replaces the GGX/Lambert list with the issue-16 plugins (glossy, phong, blinn, ward
// isotropic and anisotropic, measured) at three settings each, plus `ggx` (the default scene's
// material) at the same three and `lambert`, and the kinds with bsdf, mis and wavelet
// (docs/brdfs.md's variance table).
// --only TEXT keeps the materials whose name holds TEXT; --hotsub N sets the dense grid's cells
// per texel side near the lobe (48; 12 gives the same figures to ~1% in a tenth of the time);
// --oracle adds `oracle` to the --brdfs kinds; --detail prints (stderr) the `wavelet` mixture's
// shares and, for the sun's disc and the rest apart, each technique's second moment alone: which
// part of the integrand the product misjudges.
// --gpu adds the Vulkan tracer's `wavelet` and `oracle` (built differently from the CPU's): their
// mixtures are built on the device at the same shading point and read back (gpu_sampler_probe.h),
// and their exact variance computed on the same dense grid. (The GPU's other kinds are twins.)
#include "render/sampling/direction_sampler.h"
#include "render/testing/gpu_sampler_probe.h"
#include "render/testing/sampler_integrals.h"
#include "render/testing/sampler_test_envs.h"
#include "plugins/brdf_table.h"
#include "util/timer.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h> // getpid: concurrent runs must not share the temporary table file

using namespace wavelit;
using namespace wavelit::render;

namespace {

constexpr double kRoughness[] = {0.02, 0.05, 0.1, 0.2, 0.5, 1.0};
constexpr double kSunRatio = 1e5;
constexpr double kSunOffsetDeg = 12.0;

struct Study {
    std::string name;
    scene::Environment env;
};

glm::vec3 rotateAboutZ(glm::vec3 v, double deg) {
    const double a = deg * 3.14159265358979323846 / 180.0;
    return {float(std::cos(a) * v.x - std::sin(a) * v.y), float(std::sin(a) * v.x + std::cos(a) * v.y),
            v.z};
}

// The GPU's mixtures for every material at `point`'s geometry, per GPU-specific kind.
std::map<SamplerKind, std::vector<GpuMixture>>
probeGpu(vk::Context* gpu, const DirectionSamplerTables& wavelet,
         const DirectionSamplerTables& oracle, ShadingPoint point, size_t materialCount) {
    std::map<SamplerKind, std::vector<GpuMixture>> out;
    if (!gpu)
        return out;
    std::vector<ShadingPoint> points;
    for (size_t i = 0; i < materialCount; ++i) {
        point.material = i;
        points.push_back(point);
    }
    for (const DirectionSamplerTables* t : {&wavelet, &oracle}) {
        auto probe = probeGpuSampler(*gpu, *t, t->kind(), points, 1);
        if (!probe) {
            std::fprintf(stderr, "gpu probe: %s\n", probe.error().message().c_str());
            continue;
        }
        out[t->kind()] = probe->mixtures;
    }
    return out;
}

// A material of the study and the radius (radians) around the reflection vector where the dense
// grid refines (0: none; lobes wider than ~0.3 rad need no refinement).
struct StudyMaterial {
    SamplerMaterial material;
    double hotRadius;
};

std::vector<StudyMaterial> ggxAndLambert() {
    std::vector<StudyMaterial> out;
    for (double r : kRoughness) {
        char name[32];
        std::snprintf(name, sizeof name, "ggx r=%.2f", r);
        out.push_back({{name, plugins::findBrdf("ggx"), {glm::vec3(0.9f), float(r)}},
                       r < 0.3 ? 8.0 * r * r + 0.01 : 0.0});
    }
    out.push_back({{"lambert", plugins::findBrdf("lambert"), {glm::vec3(0.8f), 1.0f}}, 0.0});
    return out;
}

// A MERL-layout table of `glossy` at roughness r, through the file format (as a scene loads it).
std::shared_ptr<const plugins::BrdfTable> glossyTable(float r) {
    const std::vector<char> bytes = plugins::tabulateMerlBrdf(
        *plugins::findBrdf("glossy"), {glm::vec3(0.9f), r}, 24, 64, 32);
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("wavelit_variance_glossy_" + std::to_string(int(r * 100)) + "_" +
                               std::to_string(getpid()) + ".binary"))
                                 .string();
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    auto table = plugins::loadMerlBrdf(path);
    std::filesystem::remove(path);
    if (!table) {
        std::fprintf(stderr, "%s\n", table.error().message().c_str());
        std::exit(1);
    }
    return *table;
}

// The issue-16 plugins at a near-mirror-ish, a medium and a rough setting; `measured` holds
// `glossy` tabulated at the same roughness (24 x 64 x 32 bins, as the shipped example).
std::vector<StudyMaterial> issue16Brdfs() {
    std::vector<StudyMaterial> out;
    for (const char* brdf : {"ggx", "glossy", "phong", "blinn", "ward", "ward aniso", "measured"})
        for (float r : {0.1f, 0.2f, 0.5f}) {
            const bool aniso = std::string(brdf) == "ward aniso";
            const bool measured = std::string(brdf) == "measured";
            char name[48];
            std::snprintf(name, sizeof name, "%s r=%.2f%s", brdf, double(r), aniso ? " a=0.8" : "");
            plugins::BrdfParams params(glm::vec3(0.9f), r, aniso ? 0.8f : 0.0f,
                                       measured ? glossyTable(r) : nullptr);
            const plugins::Brdf* plugin = plugins::findBrdf(aniso ? "ward" : brdf);
            // The dense grid refines over the lobe's cap (the plugin's own trait) about the
            // reflection vector; a measured table is refined as the model it holds.
            const double cap = measured ? plugins::findBrdf("glossy")->lobeWidth(params).capHalfAngle
                                        : plugin->lobeWidth(params).capHalfAngle;
            out.push_back({{name, plugin, params}, r < 0.3f ? 1.5 * cap + 0.01 : 0.0});
        }
    out.push_back({{"lambert", plugins::findBrdf("lambert"), {glm::vec3(0.8f), 1.0f}}, 0.0});
    return out;
}

bool g_detail = false;   // --detail: the wavelet mixture's parts, on stderr
std::string g_only;      // --only TEXT: the materials whose name holds TEXT
int g_hotSub = 48;       // --hotsub N: the dense grid's cells per texel side near the lobe
glm::vec3 g_sun(0.0f);   // the sun study's sun (--detail splits the moments at its disc)

// Where a `wavelet` mixture loses: each technique's Var/I^2 alone, and per band of the angle
// from the reflection vector the integrand's share against each technique's probability.
void printWaveletDetail(const scene::Environment& env, const DenseIntegrandOptions& options,
                        const DirectionSampler& sampler, double integral) {
    std::fprintf(stderr, "  %s\n", sampler.describe().c_str());
    const std::vector<ComponentPdf> parts = sampler.componentPdfs(glm::vec3(0, 1, 0));
    // The sun's disc (and a texel around it) apart from the rest: each part's share of I and its
    // second moment / I^2 under the mixture and under each technique alone.
    const float cosDisc = std::cos(0.012f);
    for (int inside = 1; inside >= 0; --inside) {
        if (g_sun == glm::vec3(0.0f) && inside)
            continue;
        const DenseIntegrand part(env, [&](const glm::vec3& w) {
            const bool in = g_sun != glm::vec3(0.0f) && glm::dot(w, g_sun) > cosDisc;
            return in == bool(inside) ? sampler.brdfCos(w) : glm::vec3(0.0f);
        }, options);
        const double i2 = integral * integral;
        const EstimatorMoments mix =
            part.moments([&](const glm::vec3& w) { return sampler.pdfDouble(w); });
        std::fprintf(stderr, "  %s: I share %.4f, mixture M/I^2 %.4f;", inside ? "sun disc" : "rest",
                     part.integral() / integral, mix.secondMoment / i2);
        for (size_t c = 0; c < parts.size(); ++c) {
            const EstimatorMoments m = part.moments(
                [&](const glm::vec3& w) { return sampler.componentPdfs(w)[c].pdf; });
            std::fprintf(stderr, " %s (w %.3f) alone M/I^2 %.4g (uncovered %.2g);",
                         parts[c].technique, parts[c].weight, m.secondMoment / i2,
                         m.uncoveredIntegral / integral);
        }
        std::fprintf(stderr, "\n");
    }
}

void runStudy(const Study& study, const std::vector<SamplerKind>& kinds,
              const std::vector<StudyMaterial>& list, vk::Context* gpu) {
    const glm::vec3 n(0, 1, 0), t(1, 0, 0), b(0, 0, -1);
    const float s45 = std::sqrt(0.5f);
    const glm::vec3 wo(s45, s45, 0.0f);
    const glm::vec3 reflection(-s45, s45, 0.0f);

    std::vector<SamplerMaterial> materials;
    std::vector<StudyMaterial> kept;
    for (const StudyMaterial& m : list)
        if (g_only.empty() || m.material.name.find(g_only) != std::string::npos)
            kept.push_back(m);
    const std::vector<StudyMaterial>& chosen = kept;
    for (const StudyMaterial& m : chosen)
        materials.push_back(m.material);
    util::Timer timer;
    auto wavelet = DirectionSamplerTables::build(study.env, materials, SamplerKind::Wavelet);
    std::printf("\n### %s\n\nTables: %.0f ms in all.\n```\n%s```\n\n", study.name.c_str(),
                timer.milliseconds(), wavelet->report().c_str());
    std::shared_ptr<const DirectionSamplerTables> oracleTables;
    std::map<SamplerKind, std::vector<GpuMixture>> gpuMixtures;
    if (gpu) {
        oracleTables = DirectionSamplerTables::build(study.env, materials, SamplerKind::Oracle);
        gpuMixtures = probeGpu(gpu, *wavelet, *oracleTables, {n, t, b, wo, 0}, materials.size());
    }

    std::printf("| material |");
    for (SamplerKind k : kinds)
        std::printf(" %s |", samplerKindName(k));
    std::printf(" wavelet/oracle | mis/wavelet | bsdf/wavelet |");
    if (gpu)
        std::printf(" gpu wavelet | gpu oracle | gpu wavelet/oracle | mis/gpu wavelet |");
    std::printf("\n|---|");
    for (size_t i = 0; i < kinds.size() + 3 + (gpu ? 4 : 0); ++i)
        std::printf("---|");
    std::printf("\n");
    std::vector<std::string> timings;
    for (size_t mi = 0; mi < materials.size(); ++mi) {
        const ShadingPoint point{n, t, b, wo, mi};
        DenseIntegrandOptions options;
        options.hotSub = g_hotSub;
        if (chosen[mi].hotRadius > 0.0) { // narrow lobes: finer cells near the reflection vector
            options.hotSpots = {reflection};
            options.hotRadius = chosen[mi].hotRadius;
        }
        const DirectionSampler reference(*wavelet, SamplerKind::Bsdf, point);
        const DenseIntegrand integrand(
            study.env, [&](const glm::vec3& w) { return reference.brdfCos(w); }, options);
        const double i2 = integrand.integral() * integrand.integral();
        std::printf("| %s |", materials[mi].name.c_str());
        double vWavelet = 0, vOracle = 0, vMis = 0, vBsdf = 0;
        std::string timing = materials[mi].name + ":";
        // Under the EnvMis policy a `wavelet` vertex's NEE is the env technique alone, which the
        // tracers MIS-weight against the BSDF continuation: `mis`'s estimator, so its row shows
        // `mis`'s figure, marked (the env technique's own variance would misread as the
        // sampler's).
        const bool waveletIsMis =
            DirectionSampler(*wavelet, SamplerKind::Wavelet, point).envTechniqueOnly();
        for (SamplerKind k : kinds) {
            util::Timer build;
            const SamplerKind estimator =
                k == SamplerKind::Wavelet && waveletIsMis ? SamplerKind::Mis : k;
            const DirectionSampler sampler(*wavelet, estimator, point);
            const double buildUs = build.seconds() * 1e6;
            util::Timer draw;
            float sink = 0.0f;
            constexpr int kDraws = 2000;
            for (int s = 0; s < kDraws; ++s)
                sink += sampler.sample((s * 0.618034f) - std::floor(s * 0.618034f),
                                       (s + 0.5f) / kDraws, float((s * 7919) % kDraws) / kDraws)
                            .pdf;
            const double drawUs = draw.seconds() * 1e6 / kDraws + (sink < 0 ? 1 : 0);
            char tbuf[96];
            std::snprintf(tbuf, sizeof tbuf, " %s %.0f+%.2f us", samplerKindName(k), buildUs,
                          drawUs);
            timing += tbuf;
            util::Timer momentsTimer;
            const EstimatorMoments m =
                integrand.moments([&](const glm::vec3& w) { return sampler.pdfDouble(w); });
            std::fprintf(stderr, "%s %s: moments %.2f s over %zu points\n",
                         materials[mi].name.c_str(), samplerKindName(k), momentsTimer.seconds(),
                         integrand.pointCount());
            const double rel = m.variance() / i2;
            std::printf(" %.3g%s |", rel, estimator != k ? " (mis)" : "");
            if (k == SamplerKind::Wavelet) vWavelet = rel;
            if (k == SamplerKind::Oracle) vOracle = rel;
            if (k == SamplerKind::Mis) vMis = rel;
            if (k == SamplerKind::Bsdf) vBsdf = rel;
            if (g_detail && k == SamplerKind::Wavelet)
                printWaveletDetail(study.env, options, sampler, integrand.integral());
        }
        if (vOracle > 0.0)
            std::printf(" %.2f |", vWavelet / vOracle);
        else
            std::printf(" - |");
        std::printf(" %.2f | %.2f |", vMis / vWavelet, vBsdf / vWavelet);
        if (gpu) {
            double v[2] = {0.0, 0.0};
            int slot = 0;
            for (SamplerKind k : {SamplerKind::Wavelet, SamplerKind::Oracle}) {
                const auto it = gpuMixtures.find(k);
                if (k == SamplerKind::Wavelet && waveletIsMis) {
                    v[slot] = vMis; // the kernel's EnvMis vertex: `mis`'s estimator, as above
                } else if (it != gpuMixtures.end() && mi < it->second.size()) {
                    const GpuMixture& mix = it->second[mi];
                    v[slot] = integrand.moments([&](const glm::vec3& w) { return mix.pdf(w); })
                                  .variance() / i2;
                }
                std::printf(" %.3g%s |", v[slot], slot == 0 && waveletIsMis ? " (mis)" : "");
                ++slot;
            }
            std::printf(" %.2f | %.2f |", v[0] / v[1], vMis / v[0]);
        }
        std::printf("\n");
        std::fflush(stdout);
        timings.push_back(timing);
    }
    std::printf("\nPer shading point: construction + per-sample time (this machine, noisy):\n");
    for (const std::string& s : timings)
        std::printf("- %s\n", s.c_str());
}

// The bench target has no WAVELIT_RESOURCE_DIR definition: $WAVELIT_RESOURCE_DIR, else the
// source tree's resources/ next to this file.
std::string resourceDir() {
    if (const char* dir = std::getenv("WAVELIT_RESOURCE_DIR"))
        return dir;
    std::string file = __FILE__;
    return file.substr(0, file.rfind('/')) + "/../../resources";
}

} // namespace

int main(int argc, char** argv) {
    std::vector<SamplerKind> kinds = allSamplerKinds();
    bool quick = false, useGpu = false, issue16 = false, withOracle = false;
    std::string only; // --env NAME: run one study (sun, city, courtyard)
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (std::strcmp(argv[i], "--gpu") == 0)
            useGpu = true;
        else if (std::strcmp(argv[i], "--brdfs") == 0)
            issue16 = true;
        else if (std::strcmp(argv[i], "--env") == 0 && i + 1 < argc)
            only = argv[++i];
        else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            g_only = argv[++i];
        else if (std::strcmp(argv[i], "--hotsub") == 0 && i + 1 < argc)
            g_hotSub = std::atoi(argv[++i]);
        else if (std::strcmp(argv[i], "--oracle") == 0)
            withOracle = true;
        else if (std::strcmp(argv[i], "--detail") == 0)
            g_detail = true;
    }
    std::vector<Study> studies;
    const float s45 = std::sqrt(0.5f);
    const glm::vec3 sun = rotateAboutZ(glm::vec3(-s45, s45, 0.0f), -kSunOffsetDeg);
    if (only.empty() || only == "sun")
        g_sun = glm::normalize(sun);
    if (only.empty() || only == "sun")
        studies.push_back({"sky + 0.53 deg sun at 1e5 x sky mean, 12 deg from the reflection vector",
                           makeSunSkyEnvironment(quick ? 512 : 1024, sun, kSunRatio)});
    if (!quick)
        for (const char* name : {"city", "courtyard"}) {
            if (!only.empty() && only != name)
                continue;
            auto env = loadDownsampledEnvironment(
                resourceDir() + "/envmaps/" + name + ".exr", 512);
            if (!env) {
                std::fprintf(stderr, "%s\n", env.error().message().c_str());
                return 1;
            }
            studies.push_back({std::string(name) + ".exr (512 wide)", *env});
        }
    std::printf("# Sampler variance study\n\nRelative per-sample variance Var/I^2 of g/p (exact, "
                "dense grid); lower is better. \"(mis)\": the material's wavelet vertex is "
                "EnvMis, mis's estimator.\n");
    std::unique_ptr<vk::Context> gpu;
    if (useGpu) {
        auto ctx = vk::Context::create({"", false});
        if (!ctx) {
            std::fprintf(stderr, "--gpu: %s\n", ctx.error().message().c_str());
            return 1;
        }
        gpu = std::move(ctx.value());
    }
    // The issue-16 table compares wavelet with mis (and the plugin's own sampling); the other
    // kinds' dense moments would triple the run.
    if (issue16)
        kinds = {SamplerKind::Bsdf, SamplerKind::Mis, SamplerKind::Wavelet};
    if (issue16 && withOracle)
        kinds.push_back(SamplerKind::Oracle);
    for (const Study& s : studies)
        runStudy(s, kinds, issue16 ? issue16Brdfs() : ggxAndLambert(), gpu.get());
    return 0;
}
