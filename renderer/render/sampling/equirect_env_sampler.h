// EquirectEnvSampler: the `env` technique with the radiance's own pdf (issues 12 and 20). The
// tracers evaluate the environment as piecewise constant on the equirect texels (nearest lookup,
// render/lights/cpu_environment.h); this draws texel (x, y) with probability proportional to its
// luminance times its solid angle (2 pi / W x (cos theta_y - cos theta_{y+1})): the row by an
// inverse CDF over the rows, the column by the row's own CDF (guided_cdf.h: O(1) expected, and
// monotone in u, so the passes' stratified numbers give stratified draws), then a point uniform in
// solid angle inside the texel. The solid-angle pdf is piecewise constant on the very texels the
// radiance is: probability / solid angle, tabulated per texel in double (an O(1) lookup). Texels
// with zero radiance get zero probability (no floor): `env` alone still covers every direction
// with light, and MIS with the BSDF covers the rest.
// In the ENV-LOCAL frame (the yaw removed), like SamplerEnvironment. Two levels, not one CDF over
// all W x H texels, so that the remainder of u keeps its digits for the point inside the texel.
// The Vulkan tracer reads the tables as they are (gpu_sampler_data.h, env_exact.glsl).
// Immutable after build; const methods are thread-safe.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wavelit::render {

class EquirectEnvSampler {
public:
    // No image: one texel (the constant environment). All black: hasLight() is false.
    static EquirectEnvSampler build(const scene::Environment& env);

    bool hasLight() const { return m_lit; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    // rowCdf / rowGuide: the rows' guided CDF (height + 1 doubles, height words); columnCdf /
    // columnGuide: each row's over its columns (height x (width + 1) doubles, height x width
    // words); rowSolidAngle: one texel's per row; pdf: each texel's solid-angle pdf, row-major.
    const std::vector<double>& rowCdf() const { return m_rowCdf; }
    const std::vector<uint32_t>& rowGuide() const { return m_rowGuide; }
    const std::vector<double>& columnCdf() const { return m_columnCdf; }
    const std::vector<uint32_t>& columnGuide() const { return m_columnGuide; }
    const std::vector<double>& rowSolidAngle() const { return m_rowOmega; }
    const std::vector<double>& pdfTable() const { return m_pdf; }
    size_t bytes() const;

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
    std::vector<double> m_rowCdf, m_columnCdf, m_rowOmega, m_rowCos, m_pdf;
    std::vector<uint32_t> m_rowGuide, m_columnGuide;
};

} // namespace wavelit::render
