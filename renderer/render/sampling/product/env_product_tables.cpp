#include "render/sampling/product/env_product_tables.h"

#include "render/sampling/product/env_product_sampler.h"
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
// Budgets (docs/sampler-variance.md): the env factor keeps 512 of a window's 1024 coefficients
// (192 cost courtyard r = 0.2 2x in variance) and all of the whole sphere's (one table); the
// per-point BRDF factor is not truncated (96 cost up to 1.9x: its truncation error lands on the
// lobe's peak, and the sparse product of a full 32^2 factor costs ~20 us).
constexpr size_t kEnvKeepWindow = 512;
constexpr size_t kEnvKeepWhole = 1024;
constexpr size_t kBrdfKeep = 1024;
// Defensive BSDF share: with the product covering the lobe (and its tail), what the defensive
// parts take is mostly lost (Var >= 1/c_product - 1 for a perfect product).
constexpr double kMixBsdf = 0.03;
// Lobe refinement below the product's leaves: BRDF-weighted env levels until a cell is narrower
// than this fraction of the lobe half-width, at most kRefineMaxLevels (4 BRDF evaluations each).
constexpr double kRefineCellPerLobe = 0.1;
constexpr int kRefineMaxLevels = 3;
// A lobe narrower than this many env texels sees an environment constant across it: BSDF
// sampling is then near-ideal, and a product cannot resolve more than the env does.
constexpr double kMinLobeInEnvTexels = 2.0; // 1.0 measured 2.5x worse than mis at r = 0.05, N = 10

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
    char why[200];
    if (!env.hasLight()) {
        p.mode = ProductMode::BsdfLobe;
        p.reason = "black environment: nothing to sample but the BSDF";
        return p;
    }
    if (brdf.lobeAxis() == plugins::BrdfLobeAxis::Normal) {
        p.aroundNormal = true;
        p.lobeHalfWidth = brdf.lobeWidth(params).halfWidth;
        p.capHalfAngle = kPi;
        p.binLevel = 0;
        p.productLevel = 5;
        p.envKeep = kEnvKeepWhole;
        p.brdfKeep = kBrdfKeep;
        p.mixBsdf = kMixBsdf;
        p.refineCellAngle = kRefineCellPerLobe * p.lobeHalfWidth;
        p.refineMaxLevels = kRefineMaxLevels;
        p.reason = "diffuse: env x clamped cosine around the normal over the whole sphere, 32^2, "
                   "refined by the env pyramid";
        return p;
    }
    p.lobeHalfWidth = brdf.lobeWidth(params).halfWidth;
    const double texel = envTexelAngle(env);
    p.capHalfAngle = kCapCoverage * p.lobeHalfWidth;
    if (p.lobeHalfWidth < kMinLobeInEnvTexels * texel) {
        p.mode = ProductMode::BsdfLobe;
        std::snprintf(why, sizeof why,
                      "lobe half-width %.4f rad < env texel %.4f rad: the env is constant across "
                      "the lobe, so the BSDF samples the lobe and env sampling the rest",
                      p.lobeHalfWidth, texel);
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
                  "glossy: cap %.3f rad around the reflection vector (%s), %dx%d bins, 32^2 "
                  "product, K env %zu / brdf %zu, lobe-refined to %.3f rad, then by the env pyramid",
                  p.capHalfAngle, whole ? "whole sphere" : "window", 1 << p.binLevel,
                  1 << p.binLevel, p.envKeep, p.brdfKeep, p.refineCellAngle);
    p.reason = why;
    return p;
}

int lobeRefineLevels(const ProductPolicy& policy, const ProductWindow& window, int envLevel) {
    if (!(policy.refineCellAngle > 0.0) || policy.refineMaxLevels <= 0)
        return 0;
    const int leafLevel = window.k + policy.productLevel;
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
    char buf[160];
    std::snprintf(buf, sizeof buf, " [%d bins, %zu env tables, %.1f KiB, built in %.1f ms]",
                  binCount(), factorCount(), double(bytes()) / 1024.0, m_buildSeconds * 1e3);
    return "product: " + m_policy.reason + buf;
}

FlatProductTables MaterialProductTables::flatten() const {
    FlatProductTables f;
    f.header = {kFlatMagic, uint32_t(m_policy.binLevel), uint32_t(m_policy.productLevel),
                uint32_t(binCount()), uint32_t(factorCount())};
    for (size_t i = 0; i < m_windows.size(); ++i)
        f.header.insert(f.header.end(), {uint32_t(m_windows[i].k), uint32_t(m_windows[i].ox),
                                         uint32_t(m_windows[i].oy), uint32_t(m_factorOf[i])});
    for (const wavelet::SparseHaar& factor : m_factors) {
        f.header.push_back(uint32_t(f.nodeWords.size() / kFlatNodeWords));
        f.header.push_back(uint32_t(factor.nodes.size()));
        f.scaling.push_back(float(factor.scaling));
        for (const wavelet::SparseNode& n : factor.nodes) {
            f.nodeWords.insert(f.nodeWords.end(), {uint32_t(n.level), uint32_t(n.x), uint32_t(n.y)});
            for (double d : n.detail)
                f.nodeWords.push_back(std::bit_cast<uint32_t>(float(d)));
            for (int32_t c : n.child)
                f.nodeWords.push_back(std::bit_cast<uint32_t>(c));
        }
    }
    return f;
}

size_t MaterialProductTables::bytes() const {
    if (m_policy.mode != ProductMode::Product)
        return 0;
    // flatten()'s sizes, counted without building the copy: header (5 words, 4 per bin, 2 per
    // factor), kFlatNodeWords per node, one scaling float per factor.
    size_t nodes = 0;
    for (const wavelet::SparseHaar& factor : m_factors)
        nodes += factor.nodes.size();
    const size_t words = 5 + 4 * m_windows.size() + 3 * m_factors.size() + kFlatNodeWords * nodes;
    return 4 * words;
}

wavelet::SparseHaar unflattenFactor(const FlatProductTables& flat, int factor, int level) {
    const size_t bins = flat.header[3];
    const size_t at = 5 + 4 * bins + 2 * size_t(factor);
    const size_t first = flat.header[at], count = flat.header[at + 1];
    wavelet::SparseHaar h;
    h.level = level;
    h.scaling = flat.scaling[size_t(factor)];
    for (size_t i = 0; i < count; ++i) {
        const uint32_t* w = &flat.nodeWords[(first + i) * kFlatNodeWords];
        wavelet::SparseNode n;
        n.level = int16_t(w[0]);
        n.x = int32_t(w[1]);
        n.y = int32_t(w[2]);
        for (int d = 0; d < 3; ++d)
            n.detail[d] = std::bit_cast<float>(w[3 + d]);
        for (int c = 0; c < 4; ++c)
            n.child[c] = std::bit_cast<int32_t>(w[6 + c]);
        h.nodes.push_back(n);
    }
    return h;
}

} // namespace wavelit::render
