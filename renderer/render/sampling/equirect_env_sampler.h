// EquirectEnvSampler: the `env` technique with the radiance's own pdf (issues 12 and 20). The
// tracers evaluate the environment as piecewise constant on the equirect texels (nearest lookup,
// render/lights/cpu_environment.h); this draws texel (x, y) with probability proportional to its
// luminance times its solid angle (2 pi / W x (cos theta_y - cos theta_{y+1})): the row by an
// alias table over the rows (Walker; Vose's construction), the column by the row's own alias
// table, then a point uniform in solid angle inside the texel. O(1) per draw, where the CDFs this
// replaced took two binary searches (issue 12: a `mis` pass on lavapipe). The solid-angle pdf is
// piecewise constant on the very texels the radiance is: probability / solid angle, tabulated per
// texel in double (an O(1) lookup). Texels with zero radiance get zero probability (no floor):
// `env` alone still covers every direction with light, and MIS with the BSDF covers the rest.
// In the ENV-LOCAL frame (the yaw removed), like SamplerEnvironment. Two levels, not one table
// over all W x H texels, so that the float u keeps ~15 bits per level for the coin and the point
// inside the texel. Thresholds are floats: a slot's threshold is relative to the slot, so a sky
// texel at 1e-9 of a sun's row keeps its digits; the realised probabilities differ from the
// tabulated pdf by float rounding of the thresholds (~1e-7 relative).
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
    // One alias-table slot: keep the slot's own entry with probability `threshold`, else take
    // `alias`.
    struct AliasSlot {
        float threshold = 1.0f;
        uint32_t alias = 0;
    };
    // rows: height slots; columns: height rows of width slots; rowSolidAngle: one texel's per
    // row; pdf: each texel's solid-angle pdf, row-major.
    const std::vector<AliasSlot>& rowAlias() const { return m_rowAlias; }
    const std::vector<AliasSlot>& columnAlias() const { return m_columnAlias; }
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
    std::vector<AliasSlot> m_rowAlias, m_columnAlias;
    std::vector<double> m_rowOmega, m_pdf;
};

} // namespace wavelit::render
