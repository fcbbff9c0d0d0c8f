// CPU reference path tracer: docs/estimator.md term for term (same PCG32 streams per pixel and
// pass, same draw order, camera, env lookup, surface rules, BRDF plugins, Russian roulette), so
// its mean image and the Vulkan tracer's agree within Monte Carlo noise — and, up to float
// rounding differences between C++ and GLSL, path for path. It is the ground truth of render
// tests, so it favours clarity over speed: one sample per pixel per pass, std::thread workers
// over 16×16 tiles, accumulation in double.
//
// Samplers: only `bsdf` so far; next-event estimation of the environment and analytic lights
// (`env`, `mis`, `wavelet`, `oracle`; issue 6) plugs in at the marked place in samplePixel.
// Not thread-safe as an object (driven by one thread); renderPass uses workers internally.
#pragma once

#include "render/cpu_camera.h"
#include "render/cpu_environment.h"
#include "render/integrator.h"
#include "render/render_options.h"
#include "scene/bvh.h"
#include "scene/scene.h"

#include "plugins/brdf.h"

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace wavelit::render {

class CpuPathTracer final : public Integrator {
public:
    // threadCount 0 = std::thread::hardware_concurrency(). Errors: sampler not implemented
    // (Unsupported), unknown BRDF plugin in a material (Unsupported, names the material),
    // non-positive image size or negative bounces (Invalid).
    static util::Result<std::unique_ptr<CpuPathTracer>>
    create(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
           const RenderOptions& options, int threadCount = 0);

    util::Status renderPass() override;
    int samplesPerPixel() const override { return m_passes; }
    util::Result<util::ImageRGB> image() override;
    void resetAccumulation() override;
    std::string deviceName() const override;
    IntegratorTimings timings() const override { return m_timings; }

    // One path through pixel (x, y) in pass `pass`: the estimator's single-sample radiance.
    // Deterministic: a function of (seed, pass, pixel) only. Public so tests (and GPU-vs-CPU
    // comparisons) can look at individual paths.
    glm::vec3 samplePixel(int x, int y, int pass) const;

    int threadCount() const { return m_threadCount; }

private:
    // A material resolved once: plugin pointer and parameters, so the hot loop does no lookups.
    struct ResolvedMaterial {
        const plugins::Brdf* brdf;
        plugins::BrdfParams params;
        glm::vec3 emission;
    };

    CpuPathTracer(std::shared_ptr<const scene::Scene> scene, std::shared_ptr<const scene::Bvh> bvh,
                  const RenderOptions& options, std::vector<ResolvedMaterial> materials,
                  int threadCount);
    const ResolvedMaterial& material(float index) const;

    std::shared_ptr<const scene::Scene> m_scene;
    std::shared_ptr<const scene::Bvh> m_bvh;
    RenderOptions m_options;
    std::vector<ResolvedMaterial> m_materials; // Scene::materials order, + the default at the end
    CpuCamera m_camera;
    CpuEnvironment m_environment;
    int m_threadCount;
    std::vector<glm::dvec3> m_sum;
    int m_passes = 0;
    IntegratorTimings m_timings;
};

} // namespace wavelit::render
