// Integrator: one progressive renderer (GPU path tracer on Vulkan, or the CPU reference tracer).
// Both compute the same estimator (docs/estimator.md) so their mean images agree within noise.
// Not thread-safe: owned and driven by one thread (the render thread or the CLI's main thread).
#pragma once

#include "render/sampler_tables_cache.h"
#include "util/image.h"
#include "util/result.h"

#include <memory>
#include <string>

namespace wavelit::scene {
struct Scene;
struct Bvh;
} // namespace wavelit::scene

namespace wavelit::render {

struct IntegratorTimings {
    double bvhBuildSeconds = 0.0;
    double uploadSeconds = 0.0;
    double pipelineSeconds = 0.0; // shader compile + pipeline creation (GPU only)
    double passSeconds = 0.0;     // sum over passes since the last reset
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Adds one sample per pixel to the accumulation.
    virtual util::Status renderPass() = 0;
    virtual int samplesPerPixel() const = 0;
    // Mean radiance per pixel over the passes so far (linear Rec.709).
    virtual util::Result<util::ImageRGB> image() = 0;
    virtual void resetAccumulation() = 0;
    virtual std::string deviceName() const = 0;
    virtual IntegratorTimings timings() const = 0;
    // Validation messages seen (Vulkan debug callback); always 0 for the CPU tracer.
    virtual int validationMessageCount() const { return 0; }
    // Replaces scene and BVH (same RenderOptions) keeping devices and compiled pipelines, and
    // restarts accumulation. The default says Unsupported: RenderSession then recreates the
    // integrator, which is always correct, only slower.
    virtual util::Status setScene(std::shared_ptr<const scene::Scene> /*scene*/,
                                  std::shared_ptr<const scene::Bvh> /*bvh*/) {
        return util::makeError(util::ErrorKind::Unsupported, "", "setScene not supported");
    }
    // The direction samplers' tables in use (render report, architecture.md §7): nullptr for `bsdf` and
    // for integrators that build none.
    virtual std::shared_ptr<const DirectionSamplerTables> samplerTables() const { return nullptr; }
    // What the integrator's SamplerTablesCache built and reused since it was created.
    virtual SamplerTablesRebuilds samplerRebuilds() const { return {}; }
};

} // namespace wavelit::render
