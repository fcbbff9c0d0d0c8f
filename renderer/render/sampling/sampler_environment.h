// SamplerEnvironment: the environment as the direction samplers of issue 6 see it, built once per
// environment (rebuilt on env change sets of image and tint, turned on rotations, kept across
// intensity edits: the tracers build it at intensity 1, direction_sampler_tables.h
// tablesEnvironment).
//
// Holds, in the ENV-LOCAL frame (world rotated by -yaw about +Y, exactly as CpuEnvironment does
// before its equirect lookup, docs/estimator.md "Environment"):
//  - a conservative luminance map on the equal-area octahedral map at level N: per texel the max
//    of the tracer's nearest-texel lookup over 3x3 points (see the .cpp for why not a splat),
//    N = ceil(log2(height)) + 1 capped at `maxLevel`: one octahedral texel is then at most about
//    one equirect texel near the equator;
//  - its mip pyramid of cell averages (what product windows read as the env factor);
//  - a HierarchicalSampler over it: the fine pyramid that product samplers descend into below
//    their own leaves (architecture.md §4.1, item 1);
//  - the `env` technique itself (sampleLocal, pdfWorld): EquirectEnvSampler, the radiance's own
//    equirect texels by luminance x solid angle, whose pdf is exact where the conservative map's
//    dilates a small sun over its neighbours (docs/performance.md "Exact environment pdf").
// Rotation is an isometry, so solid-angle pdfs are the same in both frames.
// Measures: pdfLocal is per unit SOLID ANGLE (square pdf / 4 pi, the octahedral Jacobian).
// Immutable after build; const methods are thread-safe.
#pragma once

#include "render/lights/cpu_environment.h"
#include "render/sampling/equirect_env_sampler.h"
#include "scene/scene.h"
#include "wavelet/cap_map.h"
#include "wavelet/hierarchical_sampler.h"
#include "wavelet/sphere_map.h"
#include "wavelet/square_grid.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace wavelit::render {

struct SamplerEnvironmentOptions {
    int maxLevel = 10; // 1024^2 octahedral texels: finer costs memory the samplers cannot use
    int minLevel = 4;
    // Threads for the conservative map's build (0: every hardware thread). The tables are the
    // same bit for bit whatever the count, so it is no part of the tables' identity
    // (direction_sampler_tables.cpp sameEnvOptions).
    int threads = 0;
};

class SamplerEnvironment {
public:
    static SamplerEnvironment build(const scene::Environment& env,
                                    const SamplerEnvironmentOptions& options = {});
    // These tables under `env`, which differs from the one they were built from only in its
    // rotation: every table lives in the env-local frame (the octahedral map, its pyramid and
    // quadtree, the equirect CDFs are all of the unrotated map), so only the yaw and the
    // radiance lookup change. Equal to build(env) in content; a copy, not a rebuild.
    SamplerEnvironment rotatedTo(const scene::Environment& env) const;

    int level() const { return m_level; }
    // False for an all-black environment: no env technique, products fall back to the BSDF.
    bool hasLight() const { return m_fine.has_value(); }
    const wavelet::HierarchicalSampler& fine() const { return *m_fine; }
    const wavelet::OctahedralMap& map() const { return m_map; }

    // Average luminance over octahedral cell (l, x, y); l > level() reads the containing texel.
    double cellAverage(int l, int x, int y) const;

    glm::dvec3 toLocal(const glm::dvec3& world) const;
    glm::dvec3 toWorld(const glm::dvec3& local) const;

    // The env technique (EquirectEnvSampler) in env-local directions; pdfWorld reads the texel
    // the tracer's radiance lookup reads at world direction wi (CpuEnvironment::equirect).
    wavelet::DirectionSample sampleLocal(glm::dvec2 u) const;
    double pdfWorld(const glm::vec3& wi) const { return pdfUv(equirect(wi)); }
    // The same in two steps, for a tracer that reads the radiance at the same uv
    // (CpuEnvironment::radianceAt).
    glm::vec2 equirect(const glm::vec3& wi) const { return m_lookup->equirect(wi); }
    double pdfUv(const glm::vec2& uv) const { return m_fine ? m_exact.pdfUv(uv) : 0.0; }
    double pdfLocal(const glm::dvec3& local) const { return pdfWorld(glm::vec3(toWorld(local))); }
    const EquirectEnvSampler& exact() const { return m_exact; }
    // (integral of L)^2 / integral of L^2 over the sphere, in sr, on the conservative luminance
    // map: 4 pi for a constant env, ~ a sun's solid angle when the sun holds the light. What the
    // `wavelet` policy weighs against a lobe's solid angle (chooseProductPolicy).
    double effectiveSolidAngle() const { return m_effectiveSolidAngle; }

    size_t bytes() const; // sampling tables + pyramid
    double buildSeconds() const { return m_buildSeconds; }

private:
    wavelet::OctahedralMap m_map;
    int m_level = 0;
    std::vector<wavelet::SquareGrid> m_mips; // m_mips[l]: 2^l x 2^l averages
    std::optional<wavelet::HierarchicalSampler> m_fine;
    EquirectEnvSampler m_exact;
    std::optional<CpuEnvironment> m_lookup;
    double m_cosYaw = 1.0, m_sinYaw = 0.0;
    double m_effectiveSolidAngle = 0.0;
    double m_buildSeconds = 0.0;
};

// Octahedral square point of a direction, clamped into [0, 1)^2 (the last texel owns the edge).
glm::dvec2 octSquarePoint(const wavelet::OctahedralMap& map, const glm::dvec3& d);

} // namespace wavelit::render
