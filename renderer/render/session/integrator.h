// Integrator: one progressive renderer (GPU path tracer on Vulkan, or the CPU reference tracer).
// Both compute the same estimator (docs/estimator.md) so their mean images agree within noise.
// Not thread-safe: owned and driven by one thread (the render thread or the CLI's main thread).
#pragma once

#include "render/sampling/sampler_tables_cache.h"
#include "render/session/update_counts.h"
#include "scene/change_set.h"
#include "util/image.h"
#include "util/result.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

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
    // Memory, not time, reported beside: the Vulkan `wavelet` tracer's per-pixel product cache
    // (render/gpu/product_cache.h), in bytes; 0 without one.
    uint64_t productCacheBytes = 0;
};

// Polled by an integrator between the pieces of a pass; true: return from renderPass now.
using InterruptCheck = std::function<bool()>;

class Integrator {
public:
    virtual ~Integrator() = default;
    // Adds one sample per pixel to the accumulation. With an interrupt check set, an integrator
    // that splits its pass into pieces (the Vulkan tracer: dispatch pieces of ~kGpuPassPieceSeconds)
    // polls it between pieces and, when it says stop, returns ok with the pass unfinished
    // (samplesPerPixel() unchanged); the next renderPass resumes the same pass where it stopped,
    // so nothing is lost or counted twice. resetAccumulation/setScene drop an unfinished pass.
    // image() is the mean of finished passes only when called between passes.
    virtual util::Status renderPass() = 0;
    // Default: passes are not split (the CPU tracer), the check is never called.
    virtual void setInterruptCheck(InterruptCheck /*check*/) {}
    virtual int samplesPerPixel() const = 0;
    // Mean radiance per pixel over the passes so far (linear Rec.709).
    virtual util::Result<util::ImageRGB> image() = 0;
    // With RenderOptions::lightGroups: the mean radiance of each light group's layer, in
    // lightGroupsOf(scene) order (light_groups.h); their sum is image() to float rounding.
    // Without: an empty list.
    virtual util::Result<std::vector<util::ImageRGB>> groupImages() {
        return util::makeError(util::ErrorKind::Unsupported, "", "light groups not supported");
    }
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
    // Takes the scene after `changes` (and its BVH: the previous pointer when no geometry
    // changed) and updates only what the changes invalidate (architecture.md §5.B "What an edit
    // rebuilds"), then restarts accumulation. `changes` must lead from the integrator's current
    // scene to `scene`. Default: setScene (everything re-sent), always correct.
    virtual util::Status applyChanges(std::shared_ptr<const scene::Scene> scene,
                                      std::shared_ptr<const scene::Bvh> bvh,
                                      const scene::ChangeSet& /*changes*/) {
        return setScene(std::move(scene), std::move(bvh));
    }
    // Uploads (and sampler-table builds) of the last create/setScene/applyChanges; the BVH
    // counts are the session's.
    virtual UpdateCounts lastUpdate() const { return {}; }
    // The direction samplers' tables in use (render report, architecture.md §7): nullptr for `bsdf` and
    // for integrators that build none.
    virtual std::shared_ptr<const DirectionSamplerTables> samplerTables() const { return nullptr; }
    // What the integrator's SamplerTablesCache built and reused since it was created.
    virtual SamplerTablesRebuilds samplerRebuilds() const { return {}; }
};

} // namespace wavelit::render
