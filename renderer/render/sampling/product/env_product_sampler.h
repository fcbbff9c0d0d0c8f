// EnvProductSampler: one shading point's product distribution env x (BRDF x cos) over a
// ProductWindow of the octahedral square, refined below its leaves by the environment's own
// pyramid (architecture.md §4.1, items 1 and 2), with an exact pdf.
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
// Lobe refinement (optional, setLobeRefinement): for a few levels below a product leaf the env's
// four children are weighted by their cell averages times the BRDF x cos at their centres (plus
// a small floor), then the env's quadtree alone takes over. A 2^m product over a window several
// lobe widths wide sees the lobe's peak in a handful of leaves; inside them the BRDF is far from
// constant, and the product's resolution is capped (m <= 5: the GPU keeps the product in private
// memory). The weights are a deterministic function of the cell, so sample and pdf agree
// exactly; no table is needed (4 BRDF evaluations per refined level, per draw and per pdf).
// Measures: directions are ENV-LOCAL (SamplerEnvironment::toLocal); pdf per unit solid angle,
// 0 outside the window. Holds a reference to the SamplerEnvironment, which must outlive it.
#pragma once

#include "render/sampling/sampler_environment.h"
#include "render/sampling/sampler_window.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/sparse_haar.h"
#include "wavelet/square_grid.h"

#include <functional>
#include <optional>
#include <vector>

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

    // brdfCos: luminance of f(wo, wi) cos(theta_i) at the four ENV-LOCAL children centres of a
    // refined cell, in one call (a BRDF batch evaluates them together; captured by value: the
    // sampler may outlive the caller's frame). levels: how many env levels below a product leaf
    // are weighted by it (0: none; never below the env's finest level).
    using LobeBatch = std::function<void(const glm::dvec3 (&wi)[4], double (&out)[4])>;
    void setLobeRefinement(LobeBatch brdfCos, int levels);
    int lobeRefinementLevels() const { return m_refineLevels; }

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
    // The lobe-refinement weights of the four children (x-major) of global cell `cell`.
    void childWeights(wavelet::SquareCell cell, double w[4]) const;
    int refineStop(const wavelet::SquareCell& cell) const;
    // Below a product leaf: the root's quarters, then the lobe refinement, to the cell the env's
    // quadtree takes over. ONE walk for sample and pdf: drawing, each choice is made by u (and u
    // rescaled); otherwise the child holding square point p is followed (u then holds p's
    // window-local point, for the root's quarters). Multiplies `probability` by the choices'.
    wavelet::SquareCell descendBelowLeaf(wavelet::SquareCell leaf, bool drawing, glm::dvec2& u,
                                         glm::dvec2 p, double& probability) const;

    const SamplerEnvironment* m_env;
    ProductWindow m_window;
    wavelet::HierarchicalSampler m_product;
    LobeBatch m_brdfCos;
    int m_refineLevels = 0;
};

// The env factor over a window at level m: average luminance of each global cell (level k + m).
wavelet::SquareGrid windowEnvGrid(const SamplerEnvironment& env, ProductWindow window, int m);

// The tracers' product leaves (ProductBuild::Tracer, sampler_constants.h kTracerMaxProductLevel):
// the truncated env factor's average over each texel of `brdf`'s (coarser or equal) grid, i.e.
// its synthesis to that level, clamped at 0 (truncation leaves negatives), times the texel's
// env-weighted BRDF x cos (windowTabulateEnvWeightedCornersBatch). For buildDense.
wavelet::SquareGrid tracerProductLeaves(const wavelet::SparseHaar& envFactor,
                                        const wavelet::SquareGrid& brdf);

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

// Texel (x, y) of a level-m window grid: sum_s L_s f_s / sum_s L_s over its 2^shift x 2^shift
// sub-cells s (f row by row; L_s the env's average over the sub-cell), the plain mean where the
// env is black, 0 where f is 0 throughout (a texel below the horizon).
inline double envWeightedTexel(const SamplerEnvironment& env, ProductWindow window, int m,
                               int shift, int x, int y, const double* f) {
    const int supersample = 1 << shift, n = supersample * supersample;
    double plain = 0.0;
    bool lit = false;
    for (int s = 0; s < n; ++s) {
        plain += f[s];
        lit = lit || f[s] != 0.0;
    }
    if (!lit)
        return 0.0;
    double sum = 0.0, weight = 0.0;
    for (int j = 0; j < supersample; ++j)
        for (int i = 0; i < supersample; ++i) {
            int gl, gx, gy;
            window.globalCell(m + shift, x * supersample + i, y * supersample + j, gl, gx, gy);
            const double w = env.cellAverage(gl, gx, gy);
            sum += w * f[j * supersample + i];
            weight += w;
        }
    return weight > 0.0 ? sum / weight : plain / double(n);
}

// Tabulates f over a window at level m as its ENV-WEIGHTED average per texel: texel (x, y) holds
// sum_s L_s f(c_s) / sum_s L_s over its supersample^2 sub-cells s (L_s: the env's average over the
// sub-cell, c_s its centre; supersample a power of two). Times the env factor's texel average
// this is the mean of L f over the sub-cells, so the product's leaf masses are those of the
// product at the sub-cells' resolution, not a product of two averages (which misplaces a sun
// sitting in the steep part of a lobe). `values(directions, out)` writes f at each ENV-LOCAL
// direction (out is sized), all sub-cell centres in one call: a BRDF evaluates them as a batch.
template <typename Values>
wavelet::SquareGrid windowTabulateEnvWeightedBatch(const SamplerEnvironment& env,
                                                   ProductWindow window, int m, Values&& values,
                                                   int supersample = 2) {
    wavelet::SquareGrid grid(m);
    const int side = grid.size();
    int shift = 0;
    while ((1 << shift) < supersample)
        ++shift;
    const int n = supersample * supersample;
    const double inv = 1.0 / (double(side) * supersample);
    // The window's origin and side once (toGlobal's arithmetic, hoisted).
    const glm::dvec2 origin = window.origin();
    const double windowSide = window.side();
    // Sub-cell centres texel by texel, each texel's n in a row.
    std::vector<glm::dvec3> directions;
    directions.reserve(size_t(side) * size_t(side) * size_t(n));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int j = 0; j < supersample; ++j)
                for (int i = 0; i < supersample; ++i) {
                    const glm::dvec2 local((x * supersample + i + 0.5) * inv,
                                           (y * supersample + j + 0.5) * inv);
                    directions.push_back(env.map().toDirection(0, origin + local * windowSide));
                }
    std::vector<double> v(directions.size(), 0.0);
    values(directions, v);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const size_t texel = size_t(y) * size_t(side) + size_t(x);
            grid.at(x, y) = envWeightedTexel(env, window, m, shift, x, y, &v[texel * size_t(n)]);
        }
    return grid;
}

// windowTabulateEnvWeightedBatch's grid (supersample 2) with f at each sub-cell centre
// interpolated bilinearly from the texel's corners, which neighbouring texels share: (2^m + 1)^2
// evaluations instead of 4^(m + 1). The tracers' product leaves (ProductBuild::Tracer; the
// kernel's dsBuildProduct is the twin): at 16^2 leaves the BRDF evaluations were most of the
// per-pixel product cache's build, and the interpolated f costs no error per sample
// (docs/performance.md "Wavelet pass cost, round 7").
template <typename Values>
wavelet::SquareGrid windowTabulateEnvWeightedCornersBatch(const SamplerEnvironment& env,
                                                          ProductWindow window, int m,
                                                          Values&& values) {
    wavelet::SquareGrid grid(m);
    const int side = grid.size(), corners = side + 1;
    const glm::dvec2 origin = window.origin();
    const double windowSide = window.side(), inv = 1.0 / double(side);
    std::vector<glm::dvec3> directions;
    directions.reserve(size_t(corners) * size_t(corners));
    for (int y = 0; y <= side; ++y)
        for (int x = 0; x <= side; ++x)
            directions.push_back(
                env.map().toDirection(0, origin + glm::dvec2(x * inv, y * inv) * windowSide));
    std::vector<double> v(directions.size(), 0.0);
    values(directions, v);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const double* row = &v[size_t(y) * size_t(corners) + size_t(x)];
            const double k[4] = {row[0], row[1], row[corners], row[corners + 1]};
            double f[4];
            for (int c = 0; c < 4; ++c) {
                const double u = (c & 1) ? 0.75 : 0.25, w = (c >> 1) ? 0.75 : 0.25;
                f[c] = (1.0 - u) * (1.0 - w) * k[0] + u * (1.0 - w) * k[1] +
                       (1.0 - u) * w * k[2] + u * w * k[3];
            }
            grid.at(x, y) = envWeightedTexel(env, window, m, 1, x, y, f);
        }
    return grid;
}

// windowTabulateEnvWeightedBatch with f(direction) called per direction.
template <typename F>
wavelet::SquareGrid windowTabulateEnvWeighted(const SamplerEnvironment& env, ProductWindow window,
                                              int m, F&& f, int supersample = 2) {
    return windowTabulateEnvWeightedBatch(
        env, window, m,
        [&](const std::vector<glm::dvec3>& directions, std::vector<double>& out) {
            for (size_t i = 0; i < directions.size(); ++i)
                out[i] = f(directions[i]);
        },
        supersample);
}

} // namespace wavelit::render
