#include "relight/brdf_factor_table.h"

#include <algorithm>
#include <cmath>

namespace wavelit::relight {
namespace {

// cos theta from a grid coordinate u = sqrt(1 - cos theta); the horizon row is taken just above
// it (eval is 0 at the horizon, which would darken the whole last cell).
float cosFromCoordinate(float u) { return std::max(1.0f - u * u, 1e-3f); }

// Cell and fraction of coordinate u in [0, 1] on n vertices.
void locate(float u, int n, int& i, float& t) {
    const float x = std::clamp(u, 0.0f, 1.0f) * float(n - 1);
    i = std::min(int(x), n - 2);
    t = x - float(i);
}

} // namespace

bool BrdfFactorTable::suits(const plugins::Brdf& brdf, const plugins::BrdfParams& params) {
    return brdf.lobeAxis() == plugins::BrdfLobeAxis::Mirror && params.anisotropy == 0.0f && !params.table;
}

BrdfFactorTable::BrdfFactorTable(const plugins::Brdf& brdf, const plugins::BrdfParams& params,
                                 const plugins::BrdfParams* black, bool oneEval, const plugins::BrdfParams& red)
    : m_hasBlack(black != nullptr) {
    m_white.resize(size_t(kA) * kB * kC);
    if (m_hasBlack) m_black.resize(m_white.size());
    for (int a = 0; a < kA; ++a) {
        const float cosO = cosFromCoordinate(float(a) / float(kA - 1));
        const glm::vec3 wo(std::sqrt(std::max(0.0f, 1.0f - cosO * cosO)), 0.0f, cosO);
        for (int b = 0; b < kB; ++b) {
            const float cosI = cosFromCoordinate(float(b) / float(kB - 1));
            const float sinI = std::sqrt(std::max(0.0f, 1.0f - cosI * cosI));
            for (int c = 0; c < kC; ++c) {
                const float dphi = 2.0f * std::acos(float(c) / float(kC - 1));
                const glm::vec3 wi(sinI * std::cos(dphi), sinI * std::sin(dphi), cosI);
                const size_t k = (size_t(a) * kB + size_t(b)) * kC + size_t(c);
                if (m_hasBlack && oneEval) {
                    const glm::vec3 f = brdf.eval(red, wo, wi);
                    m_white[k] = glm::vec3(f.x);
                    m_black[k] = glm::vec3(f.y);
                    continue;
                }
                m_white[k] = brdf.eval(params, wo, wi);
                if (m_hasBlack) m_black[k] = brdf.eval(*black, wo, wi);
            }
        }
    }
}

glm::vec3 BrdfFactorTable::lookup(const glm::vec3& wo, const glm::vec3& wi, glm::vec3* black) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) {
        if (black) *black = glm::vec3(0.0f);
        return glm::vec3(0.0f);
    }
    // cos(dphi / 2) = |u_o + u_i| / 2 for the unit azimuth vectors; 1 (any azimuth) at the pole.
    const float ro = std::sqrt(wo.x * wo.x + wo.y * wo.y), ri = std::sqrt(wi.x * wi.x + wi.y * wi.y);
    float c = 1.0f;
    if (ro > 1e-6f && ri > 1e-6f) {
        const float sx = wo.x / ro + wi.x / ri, sy = wo.y / ro + wi.y / ri;
        c = 0.5f * std::sqrt(sx * sx + sy * sy);
    }
    int ia, ib, ic;
    float ta, tb, tc;
    locate(std::sqrt(std::max(0.0f, 1.0f - wo.z)), kA, ia, ta);
    locate(std::sqrt(std::max(0.0f, 1.0f - wi.z)), kB, ib, tb);
    locate(c, kC, ic, tc);
    const size_t base = (size_t(ia) * kB + size_t(ib)) * kC + size_t(ic);
    const size_t dA = size_t(kB) * kC, dB = size_t(kC);
    auto trilinear = [&](const std::vector<glm::vec3>& v) {
        const glm::vec3* p = v.data() + base;
        const glm::vec3 c00 = p[0] + (p[1] - p[0]) * tc;
        const glm::vec3 c01 = p[dB] + (p[dB + 1] - p[dB]) * tc;
        const glm::vec3 c10 = p[dA] + (p[dA + 1] - p[dA]) * tc;
        const glm::vec3 c11 = p[dA + dB] + (p[dA + dB + 1] - p[dA + dB]) * tc;
        const glm::vec3 c0 = c00 + (c01 - c00) * tb, c1 = c10 + (c11 - c10) * tb;
        return c0 + (c1 - c0) * ta;
    };
    if (black) *black = m_hasBlack ? trilinear(m_black) : glm::vec3(0.0f);
    return trilinear(m_white);
}

} // namespace wavelit::relight
