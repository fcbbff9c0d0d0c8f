// Per-material tables of the wavelet product sampler (issue 6; architecture.md §4.1, §5.B, §7).
//
// The paper's §5.2 localises the environment around the reflection vector w_r as "a 2D set of
// 2D wavelet images indexed by a quantised reflection direction". Here the index is an
// octahedral grid of 2^b x 2^b bins over env-local directions (the axis: w_r for GGX, the normal
// for Lambert); bin i owns a ProductWindow (sampler_window.h) that contains the cap of half-angle
// (lobe cap + bin radius) around the bin centre, and the env factor over that window at 2^m,
// Haar-transformed and truncated to its K largest coefficients. Bins with the same window share
// one factor (wide lobes: every bin has the whole sphere, so there is one table).
// The BRDF x cos factor is not tabulated here: it is tabulated over the window per shading
// point (env_product_sampler.h), so the product is centred on the exact w_r, not the bin's.
//
// The policy (ProductPolicy) is chosen per material from the lobe width against what the
// environment resolves: a lobe narrower than one env texel sees a constant environment and BSDF
// sampling is near-ideal for the lobe (architecture.md §4.1 item 2) — `mode` records the choice and `reason`
// the why, for the render report. Tables are built in double, truncated, and exported as flat
// float/uint32 arrays for the GPU (flatten(); layout in docs/wavelet-sampler.md).
// Immutable after build; thread-safe for const use.
#pragma once

#include "plugins/brdf.h"
#include "render/sampling/product/flat_product_layout.h"
#include "render/sampling/sampler_environment.h"
#include "render/sampling/sampler_window.h"
#include "wavelet/sparse_haar.h"

#include <cstdint>
#include <string>
#include <vector>

namespace wavelit::render {

// Product: the lobe is sampled by the wavelet product over a window. BsdfLobe: the lobe is
// narrower than the env resolves, so the BSDF sampler samples it (env sampling still takes the
// tail's share, see DirectionSampler).
// EnvMis: the lobe is hemisphere-wide (Lambert), only 2-4 env texels wide (a product at that
// resolution does no better than mis), or env and mirror lobe are of very different
// extent (env > kEnvMisSolidAngleRatio x lobe or lobe > kLobeMisSolidAngleRatio x env): the material's vertices use `mis`'s technique (env NEE by the exact env technique, MIS against the BSDF
// continuation; vertexSamplerKind) and no product tables are built.
enum class ProductMode { Product, BsdfLobe, EnvMis };

struct ProductPolicy {
    ProductMode mode = ProductMode::Product;
    std::string reason;
    bool aroundNormal = false; // the plugin's lobe axis: the normal (diffuse) or the mirror direction
    double lobeHalfWidth = 0.0; // radians
    double capHalfAngle = 0.0;  // lobe cap around the axis (bin radius added per bin)
    int binLevel = 0;           // 2^b x 2^b octahedral bins of the axis
    int productLevel = 5;       // m: the product is 2^m x 2^m over a window
    size_t envKeep = 0;         // K of the env factor
    size_t brdfKeep = 0;        // K of the per-point BRDF x cos factor
    // Defensive BSDF share of the `wavelet` mixture when the product samples the lobe; the env
    // share is chosen per shading point from the tail's share of the integrand (direction_sampler).
    double mixBsdf = 0.03;
    // Lobe refinement below the product's leaves (env_product_sampler.h): env levels weighted by
    // the BRDF until a cell is narrower than refineCellAngle, at most refineMaxLevels levels.
    double refineCellAngle = 0.0; // radians; 0: no refinement
    int refineMaxLevels = 0;
};

// How many env levels below the product's leaves over `window` the lobe refinement weights, for
// a product of 2^productLevel leaves a side (the policy's, or the tracers' coarser one).
int lobeRefineLevels(const ProductPolicy& policy, const ProductWindow& window, int productLevel,
                     int envLevel);

// The level of the product both path tracers form per hit for `policy` (ProductBuild::Tracer):
// the policy's productLevel capped at sampler_constants.h kTracerMaxProductLevel.
int tracerProductLevel(const ProductPolicy& policy);

ProductPolicy chooseProductPolicy(const plugins::Brdf& brdf, const plugins::BrdfParams& params,
                                  const SamplerEnvironment& env);

// Flat export for the GPU (docs/wavelet-sampler.md; word layout: flat_product_layout.h): header
// words, then per factor its nodes.
inline constexpr int kFlatNodeWords = flat_layout::kNodeWords;
struct FlatProductTables {
    std::vector<uint32_t> header;
    std::vector<uint32_t> nodeWords; // kFlatNodeWords words per SparseNode (see the doc)
    std::vector<float> scaling;      // F0(0,0) per factor
};

class MaterialProductTables {
public:
    static MaterialProductTables build(const SamplerEnvironment& env, const ProductPolicy& policy);

    const ProductPolicy& policy() const { return m_policy; }
    int binCount() const { return int(m_factorOf.size()); }
    int binOf(const glm::dvec3& axisLocal) const;
    const ProductWindow& window(int bin) const { return m_windows[size_t(bin)]; }
    const wavelet::SparseHaar& envFactor(int bin) const {
        return m_factors[size_t(m_factorOf[size_t(bin)])];
    }
    size_t factorCount() const { return m_factors.size(); }

    std::string describe() const; // one line for the render report
    size_t bytes() const;         // of the flat export
    double buildSeconds() const { return m_buildSeconds; }
    FlatProductTables flatten() const;

private:
    ProductPolicy m_policy;
    std::vector<ProductWindow> m_windows; // per bin
    std::vector<int> m_factorOf;          // per bin
    std::vector<wavelet::SparseHaar> m_factors;
    double m_buildSeconds = 0.0;
};

// Decodes one factor of a flat export (tests: the GPU layout round-trips).
wavelet::SparseHaar unflattenFactor(const FlatProductTables& flat, int factor, int level);

} // namespace wavelit::render
