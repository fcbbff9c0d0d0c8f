#include "render/sampling/equirect_env_sampler.h"

#include "render/sampling/guided_cdf.h"
#include "util/image.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::render {
namespace {

constexpr double kPi = std::numbers::pi;

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
    std::vector<double> weights(size_t(w) * size_t(h)), rowMass(static_cast<size_t>(h));
    s.m_columnCdf.reserve(size_t(h) * size_t(w + 1));
    s.m_columnGuide.reserve(size_t(h) * size_t(w));
    s.m_rowOmega.resize(size_t(h));
    s.m_rowCos.resize(size_t(h));
    for (int y = 0; y < h; ++y) {
        const double omega = texelRowSolidAngle(y, w, h);
        s.m_rowOmega[size_t(y)] = omega;
        s.m_rowCos[size_t(y)] = std::cos(kPi * y / h);
        double mass = 0.0;
        for (int x = 0; x < w; ++x) {
            const glm::vec3 c = glm::max((image ? env.image->at(x, y) : glm::vec3(1.0f)) * scale,
                                         glm::vec3(0.0f));
            weights[size_t(y) * size_t(w) + size_t(x)] = double(util::luminance(c)) * omega;
            mass += weights[size_t(y) * size_t(w) + size_t(x)];
        }
        rowMass[size_t(y)] = mass;
        appendGuidedCdf(&weights[size_t(y) * size_t(w)], w, s.m_columnCdf, s.m_columnGuide);
    }
    double total = 0.0;
    for (double m : rowMass)
        total += m;
    s.m_lit = total > 0.0 && std::isfinite(total);
    appendGuidedCdf(rowMass.data(), h, s.m_rowCdf, s.m_rowGuide);
    s.m_pdf.assign(weights.size(), 0.0);
    if (s.m_lit)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * size_t(w) + size_t(x);
                s.m_pdf[i] = weights[i] / total / s.m_rowOmega[size_t(y)];
            }
    return s;
}

double EquirectEnvSampler::texelPdf(int x, int y) const {
    return m_pdf[size_t(y) * size_t(m_width) + size_t(x)];
}

size_t EquirectEnvSampler::bytes() const {
    return (m_rowGuide.size() + m_columnGuide.size()) * sizeof(uint32_t) +
           (m_rowCdf.size() + m_columnCdf.size() + m_rowOmega.size() + m_rowCos.size() +
            m_pdf.size()) *
               sizeof(double);
}

glm::dvec3 EquirectEnvSampler::sampleLocal(glm::dvec2 u, double& pdf) const {
    const int y = pickGuidedCdf(m_rowCdf.data(), m_rowGuide.data(), m_height, u.y);
    const int x = pickGuidedCdf(&m_columnCdf[size_t(y) * size_t(m_width + 1)],
                                &m_columnGuide[size_t(y) * size_t(m_width)], m_width, u.x);
    // cos theta falls linearly across the row by omega w / (2 pi) (uniform in solid angle).
    const double c0 = m_rowCos[size_t(y)]; // cos theta at the row's top edge
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
