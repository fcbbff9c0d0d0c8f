// EquirectEnvSampler: the `env` technique with the radiance's own pdf (issues 12 and 20). The
// tracers evaluate the environment as piecewise constant on the equirect texels (nearest lookup,
// render/lights/cpu_environment.h); this draws texel (x, y) with probability proportional to its
// luminance times its solid angle (2 pi / W x (cos theta_y - cos theta_{y+1})) by a marginal CDF
// over rows and a conditional CDF per row, then a point uniform in solid angle inside it, so the
// solid-angle pdf is piecewise constant on the very texels the radiance is: probability / solid
// angle, an O(1) lookup. Texels with zero radiance get zero probability (no floor): `env` alone
// still covers every direction with light, and MIS with the BSDF covers the rest.
// In the ENV-LOCAL frame (the yaw removed), like SamplerEnvironment. The CDFs are doubles: a sun
// texel at 1e6 x the sky leaves the sky texels of its row 1e-9 of the row, below float's digits.
// The Vulkan tracer reads them as they are (gpu_sampler_data.h, sampler_environment.glsl).
// Immutable after build; const methods are thread-safe.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace wavelit::render {

class EquirectEnvSampler {
public:
    // No image: one texel (the constant environment). All black: hasLight() is false.
    static EquirectEnvSampler build(const scene::Environment& env);

    bool hasLight() const { return m_lit; }
    // The luminance integral over the sphere, sum of luminance x solid angle (envNeeShare).
    double integral() const { return m_integral; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    // marginal: height + 1 entries, 0 ... 1; rowSolidAngle: one texel's per row;
    // conditional: height rows of width + 1 entries.
    const std::vector<double>& marginal() const { return m_marginal; }
    const std::vector<double>& rowSolidAngle() const { return m_rowOmega; }
    const std::vector<double>& conditional() const { return m_conditional; }

    // Draws an env-local direction (u.y the row, u.x the column, each rescaled inside its texel);
    // pdf: that texel's solid-angle pdf.
    glm::dvec3 sampleLocal(glm::dvec2 u, double& pdf) const;
    // The solid-angle pdf of the texel that equirect point uv looks up (CpuEnvironment::equirect
    // gives uv; the same float truncation as CpuEnvironment::radiance).
    double pdfUv(const glm::vec2& uv) const;
    double texelPdf(int x, int y) const;

private:
    int m_width = 0, m_height = 0;
    bool m_lit = false;
    double m_integral = 0.0;
    std::vector<double> m_marginal, m_rowOmega, m_conditional;
};

} // namespace wavelit::render
