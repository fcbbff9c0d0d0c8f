// The direction samplers' tables as the Vulkan tracer reads them (shaders/sampling/), packed on
// the CPU so the layout can be tested without a device. Three buffers:
//   envNodes   the env's HierarchicalSampler float tables, as they are (16 bytes per node)
//   materials  one GpuSamplerMaterial per GPU material (scene materials, then the default)
//   words      every used material's flat product tables (MaterialProductTables::flatten(): header,
//              node words, scaling floats, each at its own offset), then the env's cell averages
//              at level kTailLevel (sampler_constants.h) as float bits at tailOffset (the
//              mixture's tail estimate), then the exact env technique's tables at
//              tailOffset + 4^kTailLevel (EquirectEnvSampler: width, height, its row solid
//              angles (doubles as two words, low first), the rows' guided CDF (height + 1
//              doubles, then height guide words) and each row's over its columns (height x
//              (width + 1) doubles, then height x width guide words), texel pdfs (doubles);
//              sampling/env_exact.glsl, render/sampling/guided_cdf.h; word offsets in
//              GpuEnvExactLayout). Every double sits on an 8-byte boundary (tailOffset is even,
//              each guide is padded to an even word count, the buffer to an even length): the
//              shaders read doubles and word pairs through a u64 view of the buffer, one load for
//              two words on lavapipe (docs/performance.md "Lavapipe throughput (issue 12)").
// The constants below reach the shaders as #defines (sampler_shader_defines.h).
#pragma once

#include "render/session/render_options.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_tables_cache.h"
#include "util/result.h"
#include "wavelet/hierarchical_sampler.h"

#include <cstdint>
#include <vector>

namespace wavelit::render {

// SamplerMaterial.mode codes.
inline constexpr uint32_t kGpuSamplerBsdfOnly = 0;
inline constexpr uint32_t kGpuSamplerProduct = 1;
inline constexpr uint32_t kGpuSamplerBsdfLobe = 2;
inline constexpr uint32_t kGpuSamplerOracle = 3; // the `oracle`'s per-hit dense product
inline constexpr uint32_t kGpuSamplerEnvMis = 4; // ProductMode::EnvMis: `mis`'s env NEE technique
// The finest product level the shader forms per hit, and the narrow mirror lobes' BSDF share:
// the tracers' product (sampler_constants.h kTracerMaxProductLevel, kTracerNarrowLobe*).
inline constexpr int kGpuMaxProductLevel = kTracerMaxProductLevel;
inline constexpr double kGpuNarrowLobeCap = kTracerNarrowLobeCap; // radians
inline constexpr double kGpuNarrowLobeMixBsdf = kTracerNarrowLobeMixBsdf;

// The `oracle` on the GPU: per hit a DENSE product over a window fitted to the lobe around the
// exact axis, like the CPU's (oracle_sampler.h), but at 2^5 x 2^5 leaves, each the mean of
// L x BRDF x cos over its 2 x 2 sub-cells (env-weighted, so the leaf masses are those of the 64^2
// product), then 2 levels of lobe refinement (env split x BRDF x cos at the children's centres)
// down to the CPU oracle's 2^7 resolution, then the env's quadtree. The CPU's 128^2 grid would
// take 21 KiB of private memory and ~65k BRDF evaluations per hit; this one ~4k.
inline constexpr int kGpuOracleLevel = 5;
inline constexpr uint32_t kGpuOracleRefineLevels = 2;

// Mirrors `struct SamplerMaterial` in shaders/sampling/sampler_structs.glsl (std430).
struct GpuSamplerMaterial {
    uint32_t mode = kGpuSamplerBsdfOnly;
    uint32_t tableOffset = 0;   // word offset of the flat header
    uint32_t nodeOffset = 0;    // word offset of its node words
    uint32_t scalingOffset = 0; // word offset of its scaling floats
    float mixBsdf = 0.0f;       // defensive bsdf share with the product
    float capHalfAngle = 0.0f;  // lobe cap (tail estimate without a product)
    uint32_t aroundNormal = 0;  // 1: the product's axis is the normal (Lambert)
    uint32_t refineMaxLevels = 0;   // lobe refinement below the product's leaves (the policy's)
    float refineCellAngle = 0.0f;   // radians; 0: none
};
static_assert(sizeof(GpuSamplerMaterial) == 36);
static_assert(sizeof(wavelet::HierarchicalSampler::TableNode) == 16);

struct GpuSamplerData {
    uint32_t kind = 0; // SamplerKind as its integer code
    bool lit = false;
    float envMean = 0.0f;
    float envRoulette = 0.0f; // `mis`'s shadow-ray roulette constant c (misEnvRoulette)
    uint32_t tailOffset = 0;
    uint32_t envLevel = 0; // the env map's level N
    std::vector<wavelet::HierarchicalSampler::TableNode> envNodes; // never empty
    std::vector<GpuSamplerMaterial> materials;                     // never empty
    std::vector<uint32_t> words;                                   // never empty
    size_t bytes() const;
};

// Word offsets in `words` of the exact env technique's tables at `offset` (tailOffset +
// 4^kTailLevel) for a width x height map; env_exact.glsl computes the same. All even when
// `offset` is.
struct GpuEnvExactLayout {
    uint32_t rowSolidAngle, rowCdf, rowGuide, columnCdf, columnGuide, pdfs, end;
};
constexpr uint32_t evenUp(uint32_t n) { return (n + 1) & ~1u; }
GpuEnvExactLayout gpuEnvExactLayout(uint32_t offset, uint32_t width, uint32_t height);

// `tables` from SamplerTablesCache::update; gpuMaterialCount = scene materials + 1 (the
// default). Errors (Unsupported): a product level below 1.
util::Result<GpuSamplerData> packGpuSamplers(const SceneSamplerTables& tables, SamplerKind kind,
                                             size_t gpuMaterialCount);

} // namespace wavelit::render
