#include "render/env_product_sampler.h"

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

double EnvProductSampler::integralSolidAngle() const {
    return m_product.clampedIntegral() * kFourPi * m_window.side() * m_window.side();
}

wavelet::DirectionSample EnvProductSampler::sampleLocal(glm::dvec2 u) const {
    double probability = 0.0;
    wavelet::SquareCell leaf = m_product.sampleLeaf(u, probability);
    if (leaf.level == 0) {
        // Constant product over the window: a uniformly chosen quarter, u rescaled.
        const int cx = u.x < 0.5 ? 0 : 1, cy = u.y < 0.5 ? 0 : 1;
        u = glm::min(glm::dvec2(2.0 * u.x - cx, 2.0 * u.y - cy), glm::dvec2(kOneMinusEpsilon));
        probability *= 0.25;
        leaf = {1, cx, cy};
    }
    const wavelet::SquareSample s = m_env->fine().sampleWithin(globalLeaf(leaf), u);
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
    if (leaf.level == 0) {
        probability *= 0.25;
        leaf = {1, inWindow.x < 0.5 ? 0 : 1, inWindow.y < 0.5 ? 0 : 1};
    }
    return probability * m_env->fine().pdfWithin(globalLeaf(leaf), p) / kFourPi;
}

} // namespace wavelit::render
