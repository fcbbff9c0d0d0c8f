// EnvProductSampler: one shading point's product distribution env x (BRDF x cos) over a
// ProductWindow of the octahedral square, refined below its leaves by the environment's own
// pyramid (DESIGN.md §4.1, items 1 and 2), with an exact pdf.
//
// Two ways to get the product's scaling-coefficient quadtree (2^m over the window):
//  - buildSparse: the paper's path. The env factor is a truncated Haar image (K largest, from the
//    per-reflection-direction tables, env_product_tables.h); the BRDF x cos factor is tabulated
//    over the window for THIS shading point and truncated; their product pyramid comes from the
//    wavelet core's sparse product (wavelet/product.h).
//  - buildDense: a dense grid of the product (the `oracle`, oracle_sampler.h).
// Sampling descends the product's quadtree (float tables, clamped at 0) to a leaf, then descends
// the environment's full-resolution quadtree restricted to that leaf (the BRDF taken as constant
// inside it). pdf = P(product leaf) x the env's conditional density in the leaf / 4 pi.
// A product leaf at the window's root level is split into its four quarters uniformly (the
// window's origin is only aligned to half its side, see sampler_window.h).
// Measures: directions are ENV-LOCAL (SamplerEnvironment::toLocal); pdf per unit solid angle,
// 0 outside the window. Holds a reference to the SamplerEnvironment, which must outlive it.
#pragma once

#include "render/sampler_environment.h"
#include "render/sampler_window.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/sparse_haar.h"
#include "wavelet/square_grid.h"

#include <optional>

namespace wavelit::render {

class EnvProductSampler {
public:
    // nullopt when the (clamped) product is zero everywhere: the caller falls back to the BSDF.
    static std::optional<EnvProductSampler> buildSparse(const SamplerEnvironment& env,
                                                        ProductWindow window,
                                                        const wavelet::SparseHaar& envFactor,
                                                        const wavelet::SquareGrid& brdfGrid,
                                                        size_t brdfKeep);
    static std::optional<EnvProductSampler> buildDense(const SamplerEnvironment& env,
                                                       ProductWindow window,
                                                       const wavelet::SquareGrid& productGrid);

    wavelet::DirectionSample sampleLocal(glm::dvec2 u) const;
    double pdfLocal(const glm::dvec3& local) const;

    const ProductWindow& window() const { return m_window; }
    // Integral over the window's solid angle of the (clamped) product it samples.
    double integralSolidAngle() const;
    size_t nodeCount() const { return m_product.nodeCount(); }

private:
    EnvProductSampler(const SamplerEnvironment& env, ProductWindow window,
                      wavelet::HierarchicalSampler product)
        : m_env(&env), m_window(window), m_product(std::move(product)) {}
    wavelet::SquareCell globalLeaf(wavelet::SquareCell leaf) const;

    const SamplerEnvironment* m_env;
    ProductWindow m_window;
    wavelet::HierarchicalSampler m_product;
};

// The env factor over a window at level m: average luminance of each global cell (level k + m).
wavelet::SquareGrid windowEnvGrid(const SamplerEnvironment& env, ProductWindow window, int m);

// Tabulates f(direction) over a window at level m, averaging supersample^2 points per texel.
template <typename F>
wavelet::SquareGrid windowTabulate(const wavelet::OctahedralMap& map, ProductWindow window, int m,
                                   F&& f, int supersample = 2) {
    wavelet::SquareGrid grid(m);
    const int side = grid.size();
    const double inv = 1.0 / (double(side) * supersample);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            double sum = 0.0;
            for (int j = 0; j < supersample; ++j)
                for (int i = 0; i < supersample; ++i) {
                    const glm::dvec2 local((x * supersample + i + 0.5) * inv,
                                           (y * supersample + j + 0.5) * inv);
                    sum += f(map.toDirection(0, window.toGlobal(local)));
                }
            grid.at(x, y) = sum / double(supersample * supersample);
        }
    return grid;
}

} // namespace wavelit::render
