#include "render/sampling/product/env_product_sampler.h"

#include "render/sampling/sampler_constants.h"
#include "wavelet/haar.h"
#include "wavelet/product.h"
#include "wavelet/scaling_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace wavelit::render {
namespace {

constexpr double kFourPi = 4.0 * std::numbers::pi;
constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;

// One step of the refinement's descent, serving both the draw and the pdf: drawing, the part of
// two (masses a, b) is chosen by u, which is rescaled into [0, 1); otherwise `part` (the one
// holding the point) is taken. Either way `probability` gets the part's share.
inline int takePart(bool drawing, double a, double b, int part, double& u, double& probability) {
    const double whole = a + b;
    const double p0 = whole > 0.0 ? a / whole : 0.5;
    const double p1 = 1.0 - p0;
    if (drawing) {
        part = u < p0 ? 0 : 1;
        u = std::min(part == 0 ? u / p0 : (u - p0) / p1, kOneMinusEpsilon);
    }
    probability *= part == 0 ? p0 : p1;
    return part;
}

} // namespace

wavelet::SquareGrid windowEnvGrid(const SamplerEnvironment& env, ProductWindow window, int m) {
    wavelet::SquareGrid grid(m);
    for (int y = 0; y < grid.size(); ++y)
        for (int x = 0; x < grid.size(); ++x) {
            int gl, gx, gy;
            window.globalCell(m, x, y, gl, gx, gy);
            grid.at(x, y) = env.cellAverage(gl, gx, gy);
        }
    return grid;
}

wavelet::SquareGrid tracerProductLeaves(const wavelet::SparseHaar& envFactor,
                                        const wavelet::SquareGrid& brdf) {
    // The factor's texels at its own level, then their means over each leaf: the scaling
    // coefficients at the leaf level, which the kernel synthesises directly.
    const wavelet::SquareGrid fine = wavelet::inverseHaar(envFactor.toDense());
    const int block = 1 << std::max(0, fine.level - brdf.level);
    wavelet::SquareGrid leaves(brdf.level);
    for (int y = 0; y < leaves.size(); ++y)
        for (int x = 0; x < leaves.size(); ++x) {
            double sum = 0.0;
            for (int j = 0; j < block; ++j)
                for (int i = 0; i < block; ++i)
                    sum += fine.at(x * block + i, y * block + j);
            const double envAverage = std::max(0.0, sum / double(block * block));
            leaves.at(x, y) = envAverage > 0.0 ? envAverage * brdf.at(x, y) : 0.0;
        }
    return leaves;
}

std::optional<EnvProductSampler>
EnvProductSampler::buildSparse(const SamplerEnvironment& env, ProductWindow window,
                               const wavelet::SparseHaar& envFactor,
                               const wavelet::SquareGrid& brdfGrid, size_t brdfKeep) {
    if (!env.hasLight())
        return std::nullopt;
    const wavelet::SparseHaar brdf =
        wavelet::truncate(wavelet::forwardHaar(brdfGrid), brdfKeep).coefficients;
    const std::array<const wavelet::SparseHaar*, 2> factors{&envFactor, &brdf};
    auto sampler = wavelet::HierarchicalSampler::build(wavelet::sparseProduct(factors));
    if (!sampler)
        return std::nullopt; // all-zero product
    return EnvProductSampler(env, window, std::move(*sampler));
}

std::optional<EnvProductSampler> EnvProductSampler::buildDense(const SamplerEnvironment& env,
                                                               ProductWindow window,
                                                               const wavelet::SquareGrid& grid) {
    if (!env.hasLight())
        return std::nullopt;
    auto sampler = wavelet::HierarchicalSampler::build(wavelet::ScalingTree::fromGrid(grid));
    if (!sampler)
        return std::nullopt;
    return EnvProductSampler(env, window, std::move(*sampler));
}

wavelet::SquareCell EnvProductSampler::globalLeaf(wavelet::SquareCell leaf) const {
    int gl, gx, gy;
    m_window.globalCell(leaf.level, leaf.x, leaf.y, gl, gx, gy);
    return {gl, gx, gy};
}

void EnvProductSampler::setLobeRefinement(LobeBatch brdfCos, int levels) {
    m_brdfCos = std::move(brdfCos);
    m_refineLevels = m_brdfCos ? std::max(0, levels) : 0;
}

int EnvProductSampler::refineStop(const wavelet::SquareCell& cell) const {
    return std::min(cell.level + m_refineLevels, m_env->level());
}

void EnvProductSampler::childWeights(wavelet::SquareCell cell, double w[4]) const {
    const int l = cell.level + 1;
    const double side = std::ldexp(1.0, -l);
    glm::dvec3 centre[4];
    for (int c = 0; c < 4; ++c) {
        const int cx = 2 * cell.x + (c & 1), cy = 2 * cell.y + (c >> 1);
        centre[c] = m_env->map().toDirection(0, {(cx + 0.5) * side, (cy + 0.5) * side});
        w[c] = m_env->cellAverage(l, cx, cy);
    }
    double h[4], hmax = 0.0;
    m_brdfCos(centre, h);
    for (int c = 0; c < 4; ++c) {
        h[c] = std::max(0.0, h[c]);
        hmax = std::max(hmax, h[c]);
    }
    if (hmax > 0.0 && std::isfinite(hmax))
        for (int c = 0; c < 4; ++c)
            w[c] *= h[c] + kLobeFloor * hmax;
}

double EnvProductSampler::integralSolidAngle() const {
    return m_product.clampedIntegral() * kFourPi * m_window.side() * m_window.side();
}

wavelet::SquareCell EnvProductSampler::descendBelowLeaf(wavelet::SquareCell leaf, bool drawing,
                                                        glm::dvec2& u, glm::dvec2 p,
                                                        double& probability) const {
    if (leaf.level == 0) {
        // Constant product over the window: a uniformly chosen quarter (u rescaled), or the
        // quarter holding p's window-local point (passed in `u` when not drawing).
        const int cx = u.x < 0.5 ? 0 : 1, cy = u.y < 0.5 ? 0 : 1;
        if (drawing)
            u = glm::min(glm::dvec2(2.0 * u.x - cx, 2.0 * u.y - cy), glm::dvec2(kOneMinusEpsilon));
        probability *= 0.25;
        leaf = {1, cx, cy};
    }
    wavelet::SquareCell cell = globalLeaf(leaf);
    // Lobe refinement: row by u.y, then column by u.x given the row (as HierarchicalSampler).
    for (const int stop = refineStop(cell); cell.level < stop;) {
        double w[4];
        childWeights(cell, w);
        const double scale = std::ldexp(1.0, cell.level + 1);
        const int py = std::clamp(int(p.y * scale) - 2 * cell.y, 0, 1);
        const int px = std::clamp(int(p.x * scale) - 2 * cell.x, 0, 1);
        const int cy = takePart(drawing, w[0] + w[1], w[2] + w[3], py, u.y, probability);
        const int cx = takePart(drawing, w[2 * cy], w[2 * cy + 1], px, u.x, probability);
        cell = {cell.level + 1, 2 * cell.x + cx, 2 * cell.y + cy};
    }
    return cell;
}

wavelet::DirectionSample EnvProductSampler::sampleLocal(glm::dvec2 u) const {
    double probability = 0.0;
    const wavelet::SquareCell leaf = m_product.sampleLeaf(u, probability);
    const wavelet::SquareCell cell = descendBelowLeaf(leaf, true, u, {}, probability);
    const wavelet::SquareSample s = m_env->fine().sampleWithin(cell, u);
    return {m_env->map().toDirection(0, s.point), probability * s.pdf / kFourPi};
}

double EnvProductSampler::pdfLocal(const glm::dvec3& local) const {
    const glm::dvec2 p = octSquarePoint(m_env->map(), local);
    glm::dvec2 inWindow;
    if (!m_window.toLocal(p, inWindow))
        return 0.0;
    double probability = 0.0;
    wavelet::SquareCell leaf = m_product.leafAt(inWindow, probability);
    if (!(probability > 0.0))
        return 0.0;
    const wavelet::SquareCell cell = descendBelowLeaf(leaf, false, inWindow, p, probability);
    return probability * m_env->fine().pdfWithin(cell, p) / kFourPi;
}

} // namespace wavelit::render
