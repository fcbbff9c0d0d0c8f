// DirectionSampler's mixture shares (direction_sampler.h): the second moments the env share is
// chosen from (addProduct, direction_sampler.cpp), each estimated on coarse cells or strata so a
// shading point pays a few dozen BRDF evaluations for them.
#include "render/sampling/direction_sampler.h"

#include "render/sampling/sampler_constants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {

double DirectionSampler::productLobeMoment() const {
    // The product is close to the lobe's integrand, so its second moment is close to I_lobe^2.
    const double lobe = m_product->integralSolidAngle();
    return lobe * lobe;
}

double DirectionSampler::bsdfLobeMoment() const {
    // Stratified 4x4 BSDF draws with the env's cell averages: the mean of (g/p)^2.
    const SamplerEnvironment& env = m_tables->environment();
    const int side = 1 << env.level();
    double sum = 0.0;
    for (int j = 0; j < kLobeStrata; ++j)
        for (int i = 0; i < kLobeStrata; ++i) {
            const plugins::BrdfSample s = m_material->brdf->sample(
                m_material->params, m_woLocal, (i + 0.5f) / kLobeStrata, (j + 0.5f) / kLobeStrata);
            if (!s.valid || !(s.pdf > 0.0f))
                continue;
            const glm::dvec2 p =
                octSquarePoint(env.map(), env.toLocal(glm::dvec3(fromShading(s.wi))));
            const double g = double(util::luminance(s.f)) * s.wi.z / s.pdf *
                             env.cellAverage(env.level(), int(p.x * side), int(p.y * side));
            sum += g * g;
        }
    return sum / (kLobeStrata * kLobeStrata);
}

double DirectionSampler::tailEnvMoment(const glm::dvec3& axisLocal, double capAngle) const {
    // Second moment of env sampling over the coarse cells outside the lobe (the product's
    // window, else the lobe's cap widened by a cell): sum_c (L_c fcos_c)^2 / p_c dw with
    // p_c = L_c / E, E the env's integral: sum_c L_c fcos_c^2 E dw.
    const SamplerEnvironment& env = m_tables->environment();
    const int side = 1 << kTailLevel;
    const double dw = 4.0 * std::numbers::pi / (double(side) * side);
    const double energy = env.cellAverage(0, 0, 0) * 4.0 * std::numbers::pi;
    const double cellAngle = std::sqrt(4.0 * std::numbers::pi) / side;
    const double cosCap = std::cos(std::min(capAngle + cellAngle, std::numbers::pi));
    double sum = 0.0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const glm::dvec2 p((x + 0.5) / side, (y + 0.5) / side);
            glm::dvec2 local;
            if (m_product ? m_product->window().toLocal(p, local) : false)
                continue;
            const glm::dvec3 d = env.map().toDirection(0, p);
            if (!m_product && glm::dot(d, axisLocal) > cosCap)
                continue;
            const double fcos = double(util::luminance(brdfCos(glm::vec3(env.toWorld(d)))));
            sum += env.cellAverage(kTailLevel, x, y) * fcos * fcos;
        }
    return sum * energy * dw;
}

} // namespace wavelit::render
