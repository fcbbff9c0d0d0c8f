// The `oracle` sampler's product (issue 6): the ideal the wavelet sampler approximates.
//
// Built per shading point, on the fly and at full cost: the BRDF x cos (averaged over 2x2 points
// per texel) times the env's cell averages, DENSE (no truncation), at 2^7 = 128^2 over a window
// fitted to the lobe around the EXACT axis (no quantisation), then refined below its leaves by
// the environment's full-resolution pyramid (EnvProductSampler), so the only approximations left
// are "BRDF constant inside a 128^2 window texel" and the env's octahedral resampling.
// Costs ~70k BRDF evaluations per shading point: for tests and benchmarks, not for rendering.
// Measures as EnvProductSampler (env-local directions, solid-angle pdf).
#pragma once

#include "render/sampling/product/env_product_sampler.h"
#include "render/sampling/sampler_constants.h"
#include "render/sampling/sampler_environment.h"
#include "plugins/brdf.h"

#include <functional>
#include <optional>

namespace wavelit::render {

// The oracle's defensive BSDF share: small, so it stays close to the ideal, but non-zero so tails
// outside its window (and cells the dense grid saw as zero) keep support.
inline constexpr double kOracleBsdfShare = 0.05;

// The lobe cap the oracle's window is fitted to: the plugin's lobe-width trait (plugins/brdf.h),
// so a new plugin brings its own. Shared by both tracers.
double oracleCapHalfAngle(const plugins::Brdf& brdf, const plugins::BrdfParams& params);

struct OracleOptions {
    int productLevel = 7;     // 128^2 over the window
    int depthBelowEnv = kOracleDepthBelowEnv; // windows shrink to product texels of 2^-6 env texels
};

// capHalfAngle: the lobe's cap around axisLocal (>= kWholeSphereCapAngle: the whole sphere).
// brdfCos: luminance of f(wo, wi) cos(theta_i) for an env-local wi. nullopt: all-zero product.
std::optional<EnvProductSampler>
buildOracleProduct(const SamplerEnvironment& env, const glm::dvec3& axisLocal, double capHalfAngle,
                   const std::function<double(const glm::dvec3&)>& brdfCos,
                   const OracleOptions& options = {});

} // namespace wavelit::render
