#include "wavelet/cap_map.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::wavelet {
namespace {
constexpr double kPi = std::numbers::pi;
}

glm::dvec2 squareToDisk(glm::dvec2 uv) {
    const double a = 2.0 * uv.x - 1.0, b = 2.0 * uv.y - 1.0;
    if (a == 0.0 && b == 0.0)
        return {0.0, 0.0};
    double r, theta;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        theta = (kPi / 4.0) * (b / a);
    } else {
        r = b;
        theta = kPi / 2.0 - (kPi / 4.0) * (a / b);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
}

glm::dvec2 diskToSquare(glm::dvec2 p) {
    const double r = std::sqrt(p.x * p.x + p.y * p.y);
    double a, b;
    if (r == 0.0) {
        a = b = 0.0;
    } else if (std::abs(p.x) >= std::abs(p.y)) {
        a = std::copysign(r, p.x);
        b = a * (4.0 / kPi) * std::atan(p.y / p.x);
    } else {
        b = std::copysign(r, p.y);
        a = b * (4.0 / kPi) * std::atan(p.x / p.y);
    }
    return {std::clamp(0.5 * (a + 1.0), 0.0, 1.0), std::clamp(0.5 * (b + 1.0), 0.0, 1.0)};
}

CapMap::CapMap(glm::dvec3 axis, double halfAngle)
    : m_axis(glm::normalize(axis)), m_halfAngle(std::clamp(halfAngle, 1e-9, kPi)) {
    // Frisvad-style orthonormal basis (Duff et al. 2017 branchless variant).
    const double sign = std::copysign(1.0, m_axis.z);
    const double a = -1.0 / (sign + m_axis.z);
    const double b = m_axis.x * m_axis.y * a;
    m_t = {1.0 + sign * m_axis.x * m_axis.x * a, sign * b, -sign * m_axis.x};
    m_b = {b, sign + m_axis.y * m_axis.y * a, -m_axis.y};
    const double s = std::sin(0.5 * m_halfAngle);
    m_oneMinusCos = 2.0 * s * s;
    m_solidAngle = 2.0 * kPi * m_oneMinusCos;
}

glm::dvec3 CapMap::toDirection(glm::dvec2 uv) const {
    const glm::dvec2 p = squareToDisk(uv);
    const double rho2 = p.x * p.x + p.y * p.y;
    const double oneMinusCos = rho2 * m_oneMinusCos;
    const double cosTheta = 1.0 - oneMinusCos;
    const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
    const double rho = std::sqrt(rho2);
    const glm::dvec2 dir = rho > 0.0 ? p / rho : glm::dvec2(1.0, 0.0);
    return sinTheta * (dir.x * m_t + dir.y * m_b) + cosTheta * m_axis;
}

std::optional<glm::dvec2> CapMap::toSquare(glm::dvec3 direction) const {
    const glm::dvec3 d = glm::normalize(direction);
    const double lx = glm::dot(d, m_t), ly = glm::dot(d, m_b), lz = glm::dot(d, m_axis);
    const double s2 = lx * lx + ly * ly;
    // 1 - cos(theta) without cancellation near the axis.
    const double oneMinusCos = lz > 0.0 ? s2 / (1.0 + lz) : 1.0 - lz;
    const double rho2 = oneMinusCos / m_oneMinusCos;
    // Directions a rounding error outside the rim still belong to the cap's last texels.
    constexpr double kRimTolerance = 1e-12;
    if (rho2 > 1.0 + kRimTolerance)
        return std::nullopt;
    const double rho = std::sqrt(std::min(rho2, 1.0));
    const double s = std::sqrt(s2);
    const glm::dvec2 p = s > 0.0 ? glm::dvec2(lx, ly) * (rho / s) : glm::dvec2(0.0);
    return diskToSquare(p);
}

double capHalfAngleForLobe(double lobeHalfWidth, double coverage) {
    return std::clamp(coverage * lobeHalfWidth, 1e-6, kPi);
}

DirectionSample CapSampler::sample(glm::dvec2 u) const {
    const SquareSample s = m_sampler.sample(u);
    return {m_map.toDirection(s.point), s.pdf / m_map.solidAngle()};
}

double CapSampler::pdf(glm::dvec3 direction) const {
    const auto uv = m_map.toSquare(direction);
    if (!uv)
        return 0.0;
    // A point on the square's far edge (uv = 1) belongs to the last texel.
    const glm::dvec2 p = glm::min(*uv, glm::dvec2(0x1.fffffffffffffp-1));
    return m_sampler.pdf(p) / m_map.solidAngle();
}

} // namespace wavelit::wavelet
