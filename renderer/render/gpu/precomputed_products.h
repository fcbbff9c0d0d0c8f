// Precomputed product pyramids per axis bin (issue 12: amortise the product).
//
// The Vulkan `wavelet` sampler formed a product env x BRDF x cos per hit (dense 2^m x 2^m leaves,
// ~4^m x 4 BRDF evaluations: most of a pass, docs/performance.md "Wavelet pass cost"). The
// product over a window depends on the hit only through the lobe's axis and shape, so it is
// tabulated once per environment and material, per bin of the axis, for a canonical lobe: the
// bin's centre axis as the normal, seen at normal incidence (so the mirror direction is the normal
// too). A hit reads its bin's pyramid instead of building one. The axis is binned on a 2^B x 2^B
// octahedral grid, B = max(kAxisBinLevel, the material's own bin level), each bin over the window
// of the material's bin that holds its centre (MaterialProductTables: that window holds the lobe's
// cap about any axis in the bin). Only hemisphere-wide lobes about the normal (Lambert's) get
// tables (gpu_sampler_data.cpp): at normal incidence such a lobe is exact, and its shape does not
// move with the view; every hit of such a material reads its table.
//
// Sampling stays exact whatever the table's mismatch with the hit: draws and pdfs descend the same
// table (the pdf is a function of the table, not of the integrand), the lobe refinement and the
// env's quadtree below the leaves use the hit's own BRDF as before, and the mixture's bsdf and env
// shares cover directions the table misses. Only the variance depends on the match.
//
// Leaf masses are the mean of L x BRDF x cos over the leaf's 2 x 2 sub-cells (the env's exact cell
// averages one level below the leaves, each times BRDF x cos at its centre): the per-hit product's
// env-weighted leaves, but from the untruncated env. Inner levels are float sums of their four
// children in the shader's order (dsSumPyramid), so a read pyramid equals one summed on the GPU.
#pragma once

#include "render/sampling/direction_sampler_tables.h"
#include "render/sampling/product/env_product_tables.h"
#include "render/sampling/sampler_environment.h"
#include "render/sampling/sampler_window.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace wavelit::render {

// 2^5 x 2^5 axis bins: a bin spans ~6 degrees; a diffuse table's horizon is off the hit's by at
// most ~4.5 degrees, where the lobe holds < 1% of its mass.
inline constexpr int kAxisBinLevel = 5;
// Words per bin before its pyramid: the window's k, ox, oy and the tail moment (binTailMoment).
inline constexpr int kPrecomputedBinHeaderWords = 4;
// buildPrecomputedProducts' bins: the header, the pyramid (an odd count of floats), one zero word,
// so a bin's stride is even. gpu_sampler_data.cpp puts the first bin at an odd word, so every
// pyramid starts at an odd word and each pair of sibling cells (levels >= 1 start at the odd
// (4^l - 1) / 3) on an 8-byte boundary: the shader reads a pair in one u64 load
// (dsChildProbabilities; docs/performance.md "Lavapipe throughput (issue 12)").
int precomputedBinWords(int m);

struct AxisBin {
    glm::dvec3 axis{0.0, 0.0, 1.0}; // env-local unit vector: the bin's centre
    ProductWindow window;
};

// Floats of one bin's pyramid at product level m: levels 0..m at offsets (4^l - 1) / 3.
int precomputedPyramidFloats(int m);

// The axis bin level of a material's tables (B above) and its bins, row-major.
int axisBinLevel(const MaterialProductTables& tables);
std::vector<AxisBin> axisBins(const MaterialProductTables& tables);

// One bin's pyramid at product level m over its window (precomputedPyramidFloats(m) floats).
std::vector<float> buildBinPyramid(const SamplerEnvironment& env, const SamplerMaterial& material,
                                   int m, const AxisBin& bin);

// The mixture's share rule needs the second moment of env sampling over the env's coarse tail
// cells outside the window (direction_sampler.glsl's dsTailMoment: 4^kTailLevel BRDF evaluations
// per hit). For the bin's canonical lobe it is a constant:
// sum over those cells of average x (BRDF x cos)^2 x 4 pi x cell solid angle, without the env's
// mean (the shader multiplies it in). The shares only weigh the techniques (draw and pdf read the
// same value), so the canonical lobe's figure changes the variance, never the mean.
double binTailMoment(const SamplerEnvironment& env, const SamplerMaterial& material,
                     const AxisBin& bin);

// The GPU words of every bin: its header (k, ox, oy, binTailMoment's float bits), then its
// pyramid's float bits.
std::vector<uint32_t> buildPrecomputedProducts(const SamplerEnvironment& env,
                                               const SamplerMaterial& material, int m,
                                               const MaterialProductTables& tables);

} // namespace wavelit::render
