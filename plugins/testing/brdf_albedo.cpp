#include "plugins/testing/brdf_albedo.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace wavelit::plugins {

glm::dvec3 directionalAlbedo(const Brdf& brdf, const BrdfParams& params, const glm::vec3& wo,
                             int thetaCells, int phiCells) {
    if (wo.z <= 0.0f) return glm::dvec3(0.0);
    constexpr double kPiD = 3.14159265358979323846;
    const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
    const double dt = 1.0 / thetaCells, dphi = 2.0 * kPiD / phiCells;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < thetaCells; ++i) {
        for (int a = 0; a < 2; ++a) {
            double t = (i + g[a]) * dt;
            double th = 0.5 * kPiD * t * t * t;
            double jac = std::sin(th) * 1.5 * kPiD * t * t; // sinθ dθ/dt
            for (int j = 0; j < phiCells; ++j) {
                for (int b = 0; b < 2; ++b) {
                    double phi = (j + g[b]) * dphi;
                    glm::dvec3 hd(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi),
                                  std::cos(th));
                    glm::vec3 h(hd);
                    float woh = glm::dot(wo, h);
                    if (woh <= 0.0f) continue;
                    glm::vec3 wi = glm::normalize(2.0f * woh * h - wo);
                    if (wi.z <= 0.0f) continue;
                    glm::dvec3 f(brdf.eval(params, wo, wi));
                    sum += f * (double(wi.z) * 4.0 * double(woh) * jac);
                }
            }
        }
    }
    return sum * (dt * dphi * 0.25);
}

} // namespace wavelit::plugins
