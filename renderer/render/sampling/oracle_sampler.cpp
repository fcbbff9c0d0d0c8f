#include "render/sampling/oracle_sampler.h"

#include "render/sampling/product/env_product_tables.h"
#include "render/sampling/sampler_window.h"

#include <algorithm>

namespace wavelit::render {

double oracleCapHalfAngle(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
    return brdf.lobeWidth(params).capHalfAngle;
}

std::optional<EnvProductSampler>
buildOracleProduct(const SamplerEnvironment& env, const glm::dvec3& axisLocal, double capHalfAngle,
                   const std::function<double(const glm::dvec3&)>& brdfCos,
                   const OracleOptions& options) {
    if (!env.hasLight())
        return std::nullopt;
    const int m = options.productLevel;
    const int maxK = std::max(1, env.level() + options.depthBelowEnv - m);
    const ProductWindow window = chooseWindow(env.map(), axisLocal, capHalfAngle, maxK);
    wavelet::SquareGrid grid = windowTabulate(env.map(), window, m, brdfCos, 2);
    const wavelet::SquareGrid envGrid = windowEnvGrid(env, window, m);
    for (size_t i = 0; i < grid.values.size(); ++i)
        grid.values[i] *= envGrid.values[i];
    return EnvProductSampler::buildDense(env, window, grid);
}

} // namespace wavelit::render
