#include "render/sampling/product/env_product_tables.h"

#include "render/sampling/product/env_product_sampler.h"
#include "render/sampling/product/flat_product_layout.h"
#include "render/sampling/sampler_constants.h"
#include "util/timer.h"
#include "wavelet/haar.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <tuple>

namespace wavelit::render {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr uint32_t kFlatMagic = 0x31545057; // "WPT1"

// A glossy lobe's cap covers 4.5 of its half-widths (the plugin's lobe-width trait): GGX's tail
// falls only as theta^-4, and beyond 3 half-widths it still held ~10% of the lobe, which the
// defensive techniques sampled poorly (courtyard r = 0.2: Var/I^2 0.51 with 3, 0.13 with 4.5; the
// product's resolution lost by the wider window is won back by the lobe refinement below its leaves).
constexpr double kCapCoverage = 4.5;
// A Gaussian tail (plugins/brdf.h: BrdfTail; Beckmann, Ward, cos^n lobes) holds < 1% of the lobe
// beyond 3 half-widths, so the window need not hold 4.5: in the sun study a sun 0.21 rad from the
// reflection vector in blinn's / ward's r = 0.2 tail sat inside the 4.5 window (0.36 rad, 32^2
// leaves of ~0.02 rad over a 0.057 rad Gaussian), whose product misjudged lobe and sun alike (the
// product alone: M/I^2 1.22 on the lobe vs 0.49 for BSDF sampling): Var/I^2 0.523 vs mis 0.46.
// With 3 the window is 0.24 rad in 64x64 bins, finer leaves: 0.369 (ward 0.531 -> 0.374; phong
// r = 0.1 0.258 -> 0.114; city within 1.5%, docs/brdfs.md).
constexpr double kGaussianCapCoverage = 3.0;
// Budgets (docs/sampler-variance.md): the env factor keeps 512 of a window's 1024 coefficients
// (192 cost courtyard r = 0.2 2x in variance) and all of the whole sphere's (one table); the
// per-point BRDF factor is not truncated (96 cost up to 1.9x: its truncation error lands on the
// lobe's peak, and the sparse product of a full 32^2 factor costs ~20 us).
constexpr size_t kEnvKeepWindow = 512;
constexpr size_t kEnvKeepWhole = 1024;
constexpr size_t kBrdfKeep = 1024;
// Defensive BSDF share: with the product covering the lobe (and its tail), what the defensive
// parts take is mostly lost (Var >= 1/c_product - 1 for a perfect product); both tracers use
// sampler_constants.h's, which says why it is not smaller.
constexpr double kMixBsdf = kWaveletBsdfShare;
// Lobe refinement below the product's leaves: BRDF-weighted env levels until a cell is narrower
// than this fraction of the lobe half-width, at most kRefineMaxLevels (4 BRDF evaluations each).
constexpr double kRefineCellPerLobe = 0.1;
constexpr int kRefineMaxLevels = 3;
// A lobe narrower than this many env texels sees an environment constant across it: BSDF
// sampling is then near-ideal, and a product cannot resolve more than the env does.
constexpr double kMinLobeInEnvTexels = 2.0; // 1.0 measured 2.5x worse than mis at r = 0.05, N = 10
// A lobe of kMinLobeInEnvTexels..kMinProductLobeInEnvTexels env texels: the product (16^2 leaves
// on the GPU, each about a lobe half-width, refined by BRDF x cos at one point per child) does not
// resolve the lobe against a sun of a few texels better than mis's technique does, so it cannot pay
// for its pass (2.5x mis's): the vertex takes mis's technique (EnvMis). Measured on glossy_sun
// (chrome r = 0.1 under the city sun, 2.9 texels at N = 9; docs/performance.md "Sun-lit fireflies
// of the wavelet sampler"): per sample within 10% of mis (12 seeds), also at the pixel centre's
// own hit and with the product's NEE alone. r = 0.2 under that sun (11.6 texels) won 2x per
// sample before the env technique's inverse CDF; since then glossy_r02_sun only ties mis per
// sample (docs/performance.md "Session measurements after the u64 product cache ...").
constexpr double kMinProductLobeInEnvTexels = 4.0;

double envTexelAngle(const SamplerEnvironment& env) {
    return std::sqrt(4.0 * kPi) * std::ldexp(1.0, -env.level());
}

// Largest angle between a bin's centre direction and its corners / edge midpoints.
double binRadius(const wavelet::OctahedralMap& map, int b, int x, int y, glm::dvec3 centre) {
    const double side = std::ldexp(1.0, -b);
    double radius = 0.0;
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 2; ++i) {
            const glm::dvec3 d = map.toDirection(0, {(x + 0.5 * i) * side, (y + 0.5 * j) * side});
            radius = std::max(radius, std::acos(std::clamp(glm::dot(d, centre), -1.0, 1.0)));
        }
    return radius;
}

} // namespace

ProductPolicy chooseProductPolicy(const plugins::Brdf& brdf, const plugins::BrdfParams& params,
                                  const SamplerEnvironment& env) {
    ProductPolicy p;
    char why[400];
    if (!env.hasLight()) {
        p.mode = ProductMode::BsdfLobe;
        p.reason = "black environment: nothing to sample but the BSDF";
        return p;
    }
    if (brdf.lobeAxis() == plugins::BrdfLobeAxis::Normal) {
        p.aroundNormal = true;
        const double halfWidth = brdf.lobeWidth(params).halfWidth;
        // Every hemisphere-wide lobe (Lambert-type) takes mis's technique, whatever the env
        // (docs/performance.md "Equal time, round 5"): its product never paid for its pass at
        // equal time -- under a sun env sampling follows the integrand already (the cosine is
        // near constant across the light), and under soft maps (cornell's walls, glossy_sphere's
        // ground) it bought 0-5% less error per sample for 45-65% more per pass. A narrower lobe
        // about the normal (a glossy measured table) keeps the product: its lobe sits somewhere
        // off the normal, which the cosine's extent does not describe.
        if (halfWidth >= 0.5 * kPi - 1e-9) {
            p.mode = ProductMode::EnvMis;
            p.reason = "hemisphere-wide lobe about the normal: the vertex uses mis's env NEE (no "
                       "product; the product does not pay for its pass on a cosine lobe at equal "
                       "time)";
            return p;
        }
        p.lobeHalfWidth = halfWidth;
        p.capHalfAngle = kPi;
        p.binLevel = 0;
        p.productLevel = 5;
        p.envKeep = kEnvKeepWhole;
        p.brdfKeep = kBrdfKeep;
        p.mixBsdf = kMixBsdf;
        p.refineCellAngle = kRefineCellPerLobe * p.lobeHalfWidth;
        p.refineMaxLevels = kRefineMaxLevels;
        std::snprintf(why, sizeof why,
                      "lobe about the normal narrower than the hemisphere (half-width %.4f rad): "
                      "env x BRDF x cos around the normal over the whole sphere, 32^2, refined by "
                      "the env pyramid",
                      halfWidth);
        p.reason = why;
        return p;
    }
    const plugins::BrdfLobeWidth lobe = brdf.lobeWidth(params);
    p.lobeHalfWidth = lobe.halfWidth;
    const double texel = envTexelAngle(env);
    p.capHalfAngle = (lobe.tail == plugins::BrdfTail::Gaussian ? kGaussianCapCoverage
                                                               : kCapCoverage) *
                     p.lobeHalfWidth;
    if (p.lobeHalfWidth < kMinLobeInEnvTexels * texel) {
        p.mode = ProductMode::BsdfLobe;
        std::snprintf(why, sizeof why,
                      "lobe half-width %.4f rad < env texel %.4f rad: the env is constant across "
                      "the lobe, so the BSDF samples the lobe and env sampling the rest",
                      p.lobeHalfWidth, texel);
        p.reason = why;
        return p;
    }
    // A uniform env (a constant one: 4 pi sr, at the octahedral map's minimum level, whose texels
    // are no detail of the light) is exempt from this rule, and the env-wider side of the extents
    // rule below holds it to kUniformEnvMisSolidAngleRatio: its product is the lobe itself, which
    // the refinement resolves (the furnace's ggx r = 0.6, 3.25 such texels and 1/8 of the env,
    // reached 1% at 44 passes; mis's estimator needs ~750-1100).
    const bool uniformEnv = env.effectiveSolidAngle() >= 4.0 * kPi * (1.0 - 1e-6);
    if (!uniformEnv && p.lobeHalfWidth < kMinProductLobeInEnvTexels * texel) {
        p.mode = ProductMode::EnvMis;
        std::snprintf(why, sizeof why,
                      "lobe half-width %.4f rad < %g env texels (%.4f rad): a product at this "
                      "resolution samples the lobe no better than mis's env NEE, so the vertex "
                      "uses it (no per-hit product)",
                      p.lobeHalfWidth, kMinProductLobeInEnvTexels, texel);
        p.reason = why;
        return p;
    }
    // The two-sided extents rule (sampler_constants.h): the product only where env and lobe are
    // of comparable extent, kEnvMisSolidAngleRatio on the env-wider side, kLobeMisSolidAngleRatio
    // on the lobe-wider side.
    const double lobeSolidAngle = 2.0 * kPi * (1.0 - std::cos(p.lobeHalfWidth));
    const double envSolidAngle = env.effectiveSolidAngle();
    const double envWiderRatio = uniformEnv ? kUniformEnvMisSolidAngleRatio : kEnvMisSolidAngleRatio;
    if (envSolidAngle > envWiderRatio * lobeSolidAngle) {
        p.mode = ProductMode::EnvMis;
        std::snprintf(why, sizeof why,
                      "env wider than the lobe: env effective solid angle %.4g sr > %g x the "
                      "lobe's %.4g sr (ratio %.3g): BSDF sampling follows the env across the "
                      "lobe, so the vertex uses mis's env NEE (no per-hit product)",
                      envSolidAngle, envWiderRatio, lobeSolidAngle,
                      envSolidAngle / lobeSolidAngle);
        p.reason = why;
        return p;
    }
    if (lobeSolidAngle > kLobeMisSolidAngleRatio * envSolidAngle) {
        p.mode = ProductMode::EnvMis;
        std::snprintf(why, sizeof why,
                      "lobe wider than the env: the lobe's %.4g sr > %g x the env effective solid "
                      "angle %.4g sr (ratio %.3g): the light sits inside the lobe, so mis's env "
                      "NEE follows the integrand and the vertex uses it (no per-hit product)",
                      lobeSolidAngle, kLobeMisSolidAngleRatio, envSolidAngle,
                      lobeSolidAngle / envSolidAngle);
        p.reason = why;
        return p;
    }
    const bool whole = p.capHalfAngle >= kWholeSphereCapAngle;
    p.binLevel = whole ? 0 : (p.capHalfAngle < 0.3 ? 6 : 5);
    p.productLevel = 5;
    p.envKeep = whole ? kEnvKeepWhole : kEnvKeepWindow;
    p.brdfKeep = kBrdfKeep;
    p.mixBsdf = kMixBsdf;
    p.refineCellAngle = kRefineCellPerLobe * p.lobeHalfWidth;
    p.refineMaxLevels = kRefineMaxLevels;
    std::snprintf(why, sizeof why,
                  "mirror lobe: cap %.3f rad around the reflection vector (%s), %dx%d bins, 32^2 "
                  "product, K env %zu / brdf %zu, lobe-refined to %.3f rad, then by the env "
                  "pyramid; comparable extents: env effective solid angle %.4g sr, the lobe's "
                  "%.4g sr (env / lobe %.3g, within %g..%g)",
                  p.capHalfAngle, whole ? "whole sphere" : "window", 1 << p.binLevel,
                  1 << p.binLevel, p.envKeep, p.brdfKeep, p.refineCellAngle, envSolidAngle,
                  lobeSolidAngle, envSolidAngle / lobeSolidAngle, 1.0 / kLobeMisSolidAngleRatio,
                  kEnvMisSolidAngleRatio);
    p.reason = why;
    return p;
}

int tracerProductLevel(const ProductPolicy& policy) {
    return std::min(policy.productLevel, kTracerMaxProductLevel);
}

int lobeRefineLevels(const ProductPolicy& policy, const ProductWindow& window, int productLevel,
                     int envLevel) {
    if (!(policy.refineCellAngle > 0.0) || policy.refineMaxLevels <= 0)
        return 0;
    const int leafLevel = window.k + productLevel;
    double cell = std::sqrt(4.0 * kPi) * std::ldexp(1.0, -leafLevel);
    int levels = 0;
    while (levels < policy.refineMaxLevels && leafLevel + levels < envLevel &&
           cell > policy.refineCellAngle) {
        cell *= 0.5;
        ++levels;
    }
    return levels;
}

MaterialProductTables MaterialProductTables::build(const SamplerEnvironment& env,
                                                   const ProductPolicy& policy) {
    util::Timer timer;
    MaterialProductTables t;
    t.m_policy = policy;
    if (policy.mode != ProductMode::Product)
        return t;
    const int b = policy.binLevel, m = policy.productLevel;
    const int bins = 1 << b;
    const int maxK = std::max(1, env.level() + 2 - m);
    std::map<std::tuple<int, int, int>, int> factorOfWindow;
    t.m_windows.resize(size_t(bins) * size_t(bins));
    t.m_factorOf.resize(t.m_windows.size());
    for (int y = 0; y < bins; ++y)
        for (int x = 0; x < bins; ++x) {
            const size_t bin = size_t(y) * size_t(bins) + size_t(x);
            ProductWindow w;
            if (policy.capHalfAngle < kWholeSphereCapAngle) {
                const glm::dvec3 centre = env.map().toDirection(
                    0, {(x + 0.5) / bins, (y + 0.5) / bins});
                const double angle =
                    policy.capHalfAngle + binRadius(env.map(), b, x, y, centre);
                w = chooseWindow(env.map(), centre, angle, maxK);
            }
            t.m_windows[bin] = w;
            const auto key = std::make_tuple(w.k, w.ox, w.oy);
            auto it = factorOfWindow.find(key);
            if (it == factorOfWindow.end()) {
                const wavelet::SquareGrid grid = windowEnvGrid(env, w, m);
                t.m_factors.push_back(
                    wavelet::truncate(wavelet::forwardHaar(grid), policy.envKeep).coefficients);
                it = factorOfWindow.emplace(key, int(t.m_factors.size()) - 1).first;
            }
            t.m_factorOf[bin] = it->second;
        }
    t.m_buildSeconds = timer.seconds();
    return t;
}

int MaterialProductTables::binOf(const glm::dvec3& axisLocal) const {
    const int bins = 1 << m_policy.binLevel;
    const glm::dvec2 p = octSquarePoint(wavelet::OctahedralMap{}, axisLocal);
    const int x = std::min(int(p.x * bins), bins - 1), y = std::min(int(p.y * bins), bins - 1);
    return y * bins + x;
}

std::string MaterialProductTables::describe() const {
    if (m_policy.mode == ProductMode::BsdfLobe)
        return "bsdf lobe: " + m_policy.reason;
    if (m_policy.mode == ProductMode::EnvMis)
        return "env mis: " + m_policy.reason;
    char buf[160];
    std::snprintf(buf, sizeof buf, " [%d bins, %zu env tables, %.1f KiB, built in %.1f ms]",
                  binCount(), factorCount(), double(bytes()) / 1024.0, m_buildSeconds * 1e3);
    return "product: " + m_policy.reason + buf;
}

FlatProductTables MaterialProductTables::flatten() const {
    FlatProductTables f;
    namespace fl = flat_layout;
    f.header.assign(size_t(fl::factorWordsAt(binCount(), int(factorCount()))), 0u);
    f.header[fl::kMagic] = kFlatMagic;
    f.header[fl::kBinLevel] = uint32_t(m_policy.binLevel);
    f.header[fl::kProductLevel] = uint32_t(m_policy.productLevel);
    f.header[fl::kBinCount] = uint32_t(binCount());
    f.header[fl::kFactorCount] = uint32_t(factorCount());
    for (size_t i = 0; i < m_windows.size(); ++i) {
        uint32_t* bin = &f.header[size_t(fl::binWordsAt(int(i)))];
        bin[fl::kBinK] = uint32_t(m_windows[i].k);
        bin[fl::kBinOx] = uint32_t(m_windows[i].ox);
        bin[fl::kBinOy] = uint32_t(m_windows[i].oy);
        bin[fl::kBinFactor] = uint32_t(m_factorOf[i]);
    }
    for (size_t i = 0; i < m_factors.size(); ++i) {
        const wavelet::SparseHaar& factor = m_factors[i];
        uint32_t* words = &f.header[size_t(fl::factorWordsAt(binCount(), int(i)))];
        words[fl::kFactorFirstNode] = uint32_t(f.nodeWords.size() / fl::kNodeWords);
        words[fl::kFactorNodeCount] = uint32_t(factor.nodes.size());
        f.scaling.push_back(float(factor.scaling));
        for (const wavelet::SparseNode& n : factor.nodes) {
            uint32_t node[fl::kNodeWords];
            node[fl::kNodeLevel] = uint32_t(n.level);
            node[fl::kNodeX] = uint32_t(n.x);
            node[fl::kNodeY] = uint32_t(n.y);
            for (int d = 0; d < 3; ++d)
                node[fl::kNodeDetail + d] = std::bit_cast<uint32_t>(float(n.detail[size_t(d)]));
            for (int c = 0; c < 4; ++c)
                node[fl::kNodeChild + c] = std::bit_cast<uint32_t>(int32_t(n.child[size_t(c)]));
            f.nodeWords.insert(f.nodeWords.end(), node, node + fl::kNodeWords);
        }
    }
    return f;
}

size_t MaterialProductTables::bytes() const {
    if (m_policy.mode != ProductMode::Product)
        return 0;
    // flatten()'s sizes, counted without building the copy: the header (flat_product_layout.h),
    // kNodeWords per node, one scaling float per factor.
    size_t nodes = 0;
    for (const wavelet::SparseHaar& factor : m_factors)
        nodes += factor.nodes.size();
    const size_t words =
        size_t(flat_layout::factorWordsAt(int(m_windows.size()), int(m_factors.size()))) +
        m_factors.size() + size_t(flat_layout::kNodeWords) * nodes;
    return 4 * words;
}

wavelet::SparseHaar unflattenFactor(const FlatProductTables& flat, int factor, int level) {
    namespace fl = flat_layout;
    const size_t at =
        size_t(fl::factorWordsAt(int(flat.header[size_t(fl::kBinCount)]), factor));
    const size_t first = flat.header[at + fl::kFactorFirstNode];
    const size_t count = flat.header[at + fl::kFactorNodeCount];
    wavelet::SparseHaar h;
    h.level = level;
    h.scaling = flat.scaling[size_t(factor)];
    for (size_t i = 0; i < count; ++i) {
        const uint32_t* w = &flat.nodeWords[(first + i) * fl::kNodeWords];
        wavelet::SparseNode n;
        n.level = int16_t(w[fl::kNodeLevel]);
        n.x = int32_t(w[fl::kNodeX]);
        n.y = int32_t(w[fl::kNodeY]);
        for (int d = 0; d < 3; ++d)
            n.detail[d] = std::bit_cast<float>(w[fl::kNodeDetail + d]);
        for (int c = 0; c < 4; ++c)
            n.child[c] = std::bit_cast<int32_t>(w[fl::kNodeChild + c]);
        h.nodes.push_back(n);
    }
    return h;
}

} // namespace wavelit::render
