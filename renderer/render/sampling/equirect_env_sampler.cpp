#include "render/sampling/equirect_env_sampler.h"

#include "util/image.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBelowOne = 0x1.fffffffffffffp-1;

// Normalises weights w[0..n) into a CDF of n + 1 entries (0 ... 1); all zero: uniform.
void buildCdf(const double* w, int n, double* cdf) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += w[i];
    cdf[0] = 0.0;
    double run = 0.0;
    for (int i = 0; i < n; ++i) {
        run += sum > 0.0 ? w[i] : 1.0;
        cdf[i + 1] = run / (sum > 0.0 ? sum : double(n));
    }
    cdf[n] = 1.0;
}

// The interval i of cdf[0..n] with cdf[i] <= u < cdf[i + 1] (never an empty one); u rescaled.
int pick(const double* cdf, int n, double& u) {
    const int i = std::clamp(int(std::upper_bound(cdf, cdf + n + 1, u) - cdf) - 1, 0, n - 1);
    const double width = cdf[i + 1] - cdf[i];
    u = width > 0.0 ? std::min((u - cdf[i]) / width, kBelowOne) : 0.5;
    return i;
}

// 2 pi / w x (cos theta_y - cos theta_{y+1}), as a product of sines: no cancellation at the poles.
double texelRowSolidAngle(int y, int w, int h) {
    return 2.0 * kPi / w * 2.0 * std::sin(kPi * (2 * y + 1) / (2.0 * h)) * std::sin(kPi / (2.0 * h));
}

} // namespace

EquirectEnvSampler EquirectEnvSampler::build(const scene::Environment& env) {
    EquirectEnvSampler s;
    const bool image = env.image && !env.image->empty();
    s.m_width = image ? env.image->width : 1;
    s.m_height = image ? env.image->height : 1;
    const int w = s.m_width, h = s.m_height;
    const glm::vec3 scale = env.intensity * env.tint;
    std::vector<double> weights(static_cast<size_t>(w)), rowMass(static_cast<size_t>(h));
    s.m_conditional.resize(size_t(h) * size_t(w + 1));
    s.m_rowOmega.resize(size_t(h));
    for (int y = 0; y < h; ++y) {
        const double omega = texelRowSolidAngle(y, w, h);
        s.m_rowOmega[size_t(y)] = omega;
        double mass = 0.0;
        for (int x = 0; x < w; ++x) {
            const glm::vec3 c = glm::max((image ? env.image->at(x, y) : glm::vec3(1.0f)) * scale,
                                         glm::vec3(0.0f));
            weights[size_t(x)] = double(util::luminance(c)) * omega;
            mass += weights[size_t(x)];
        }
        rowMass[size_t(y)] = mass;
        buildCdf(weights.data(), w, &s.m_conditional[size_t(y) * size_t(w + 1)]);
    }
    double total = 0.0;
    for (double m : rowMass)
        total += m;
    s.m_lit = total > 0.0 && std::isfinite(total);
    s.m_integral = s.m_lit ? total : 0.0;
    s.m_marginal.resize(size_t(h) + 1);
    buildCdf(rowMass.data(), h, s.m_marginal.data());
    return s;
}

double EquirectEnvSampler::texelPdf(int x, int y) const {
    if (!m_lit)
        return 0.0;
    const double* row = &m_conditional[size_t(y) * size_t(m_width + 1)];
    const double p = (m_marginal[size_t(y) + 1] - m_marginal[size_t(y)]) * (row[x + 1] - row[x]);
    return p / m_rowOmega[size_t(y)];
}

glm::dvec3 EquirectEnvSampler::sampleLocal(glm::dvec2 u, double& pdf) const {
    const int y = pick(m_marginal.data(), m_height, u.y);
    const int x = pick(&m_conditional[size_t(y) * size_t(m_width + 1)], m_width, u.x);
    // cos theta falls linearly across the row by omega w / (2 pi) (uniform in solid angle).
    const double c0 = std::cos(kPi * y / m_height);
    const double cosTheta =
        std::clamp(c0 - m_rowOmega[size_t(y)] * m_width / (2.0 * kPi) * u.y, -1.0, 1.0);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * ((x + u.x) / m_width - 0.5);
    pdf = texelPdf(x, y);
    return {sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)};
}

double EquirectEnvSampler::pdfUv(const glm::vec2& uv) const {
    if (!m_lit)
        return 0.0;
    const float fx = uv.x * float(m_width), fy = uv.y * float(m_height);
    const int x = fx > 0.0f ? std::min(int(fx), m_width - 1) : 0;
    const int y = fy > 0.0f ? std::min(int(fy), m_height - 1) : 0;
    return texelPdf(x, y);
}

} // namespace wavelit::render
