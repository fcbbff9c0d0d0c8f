// GpuSamplerProbe: runs the Vulkan tracer's direction samplers (shaders/sampling/, the shaders
// the tracer compiles, with the same generated defines) at given shading points, outside the
// tracer, and reads back what each mixture was built from (technique shares, product window, the
// product pyramid of the `wavelet` and `oracle` kinds) plus draws with their returned pdfs.
// GpuMixture then evaluates that mixture's pdf on the CPU WITHOUT a twin of the shader's walk:
// the GPU's product leaves go into the production EnvProductSampler (buildDense, with the lobe
// refinement the GPU used), whose descent is the one the shader mirrors, and the bsdf and env
// parts are the plugin's and SamplerEnvironment's. (Evaluating the dense chi-square and variance
// integrals on the device instead would take ~1e7 shader pdfs per configuration on lavapipe.)
// What it is for: judging the GPU samplers where they are not twins of the CPU's (chi-square in
// gpu_product_sampler_test.cpp) and computing their EXACT per-sample variance on the CPU (the
// GPU variance study, tests/bench/gpu_sampler_variance_bench.cpp). Not used by rendering.
#pragma once

#include "render/sampling/direction_sampler.h"
#include "render/sampling/product/env_product_sampler.h"
#include "render/gpu/gpu_sampler_data.h"
#include "util/result.h"
#include "vk/context.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace wavelit::render {

// The mixture one shading point got on the GPU, and its pdf (solid angle, world directions).
struct GpuMixture {
    double cProduct = 0, cBsdf = 0, cEnv = 0, cUniform = 0, cCosine = 0;
    int k = 0, ox = 0, oy = 0, m = 0, refineLevels = 0;
    std::vector<double> mass; // the product pyramid, levels 0..m at offsets (4^l - 1) / 3
    const SamplerEnvironment* env = nullptr;
    const SamplerMaterial* material = nullptr;
    ShadingPoint point;
    // The product technique: the pyramid's leaves in EnvProductSampler (empty without a product).
    std::optional<EnvProductSampler> product;

    double pdf(const glm::vec3& wi) const;
    double brdfCos(const glm::vec3& wi) const; // luminance of f cos, world direction
};

struct GpuProbeDraw {
    glm::vec3 wi{0.0f};
    float pdf = -1.0f; // < 0: the sampler returned no direction
};

struct GpuProbeResult {
    std::vector<GpuMixture> mixtures;        // one per point
    std::vector<GpuProbeDraw> draws;         // drawsPerPoint per point, point-major
    int validationMessages = 0;
};

// points[i].material indexes `tables`' materials; the probe packs one sampler material per point.
// `tables` must outlive the result (the mixtures point into it). drawsPerPoint >= 1.
util::Result<GpuProbeResult> probeGpuSampler(vk::Context& context,
                                             const DirectionSamplerTables& tables, SamplerKind kind,
                                             const std::vector<ShadingPoint>& points,
                                             int drawsPerPoint, uint64_t seed = 7919);

// Floats in the shader's product pyramid for `kind` (levels 0..4; 0..5 for the oracle).
int gpuPyramidFloats(SamplerKind kind);

} // namespace wavelit::render
