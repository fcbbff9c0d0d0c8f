#include "render/testing/sampler_integrals.h"

#include "render/lights/cpu_environment.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {
namespace {
constexpr double kPi = std::numbers::pi;
} // namespace

DenseIntegrand::DenseIntegrand(const scene::Environment& env,
                               const std::function<glm::vec3(const glm::vec3&)>& brdfCos,
                               const DenseIntegrandOptions& options) {
    const CpuEnvironment lookup(env);
    const bool image = env.image && !env.image->empty();
    const int w = image ? env.image->width : options.constantEnvWidth;
    const int h = image ? env.image->height : options.constantEnvWidth / 2;
    // Env-local -> world: the inverse of CpuEnvironment's rotation by -yaw (same float rounding).
    const float yaw = env.rotationDeg * float(kPi / 180.0);
    const double c = std::cos(yaw), s = std::sin(yaw);
    std::vector<glm::dvec3> hot;
    for (const glm::vec3& d : options.hotSpots)
        hot.push_back(glm::normalize(glm::dvec3(d)));
    const double dPhi = 2.0 * kPi / w;
    for (int y = 0; y < h; ++y) {
        const double z0 = std::cos(kPi * y / h), z1 = std::cos(kPi * (y + 1) / h);
        const double thetaMid = kPi * (y + 0.5) / h;
        const double texelRadius = 0.75 * std::max(kPi / h, dPhi * std::sin(thetaMid)) + 1e-9;
        for (int x = 0; x < w; ++x) {
            const double phiMid = (x + 0.5) * dPhi - kPi;
            auto direction = [&](double cosT, double phi) {
                const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
                const glm::dvec3 l(sinT * std::cos(phi), cosT, sinT * std::sin(phi));
                return glm::dvec3(c * l.x + s * l.z, l.y, -s * l.x + c * l.z);
            };
            int sub = options.sub;
            if (!hot.empty()) {
                const glm::dvec3 centre = direction(std::cos(thetaMid), phiMid);
                for (const glm::dvec3& spot : hot)
                    if (std::acos(std::clamp(glm::dot(centre, spot), -1.0, 1.0)) <
                        options.hotRadius + texelRadius)
                        sub = std::max(sub, options.hotSub);
            }
            const double dw = (z0 - z1) * dPhi / (double(sub) * sub);
            for (int j = 0; j < sub; ++j)
                for (int i = 0; i < sub; ++i) {
                    const double cosT = z0 + (z1 - z0) * (j + 0.5) / sub;
                    const double phi = (x + (i + 0.5) / sub) * dPhi - kPi;
                    const glm::vec3 d = glm::vec3(direction(cosT, phi));
                    const double g = double(util::luminance(brdfCos(d) * lookup.radiance(d)));
                    if (g > 0.0 && std::isfinite(g)) {
                        m_dirs.push_back(d);
                        m_g.push_back(g);
                        m_dw.push_back(dw);
                        m_integral += g * dw;
                    }
                }
        }
    }
}

EstimatorMoments DenseIntegrand::moments(const std::function<double(const glm::vec3&)>& pdf) const {
    EstimatorMoments m;
    m.integral = m_integral;
    for (size_t i = 0; i < m_dirs.size(); ++i) {
        const double p = pdf(m_dirs[i]);
        if (p > 0.0)
            m.secondMoment += m_g[i] * m_g[i] / p * m_dw[i];
        else
            m.uncoveredIntegral += m_g[i] * m_dw[i];
    }
    return m;
}

} // namespace wavelit::render
