// RenderSession: the public entry point of rendering for the CLI and the editor. Owns a copy of
// the scene, the BVH and one Integrator (Vulkan or CPU, per RenderOptions::device). Driven by one
// thread; the editor runs it on its render thread and hands edits over between passes.
#pragma once

#include "render/session/integrator.h"
#include "render/session/light_groups.h"
#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/image.h"
#include "util/result.h"

#include <memory>
#include <string>

namespace wavelit::render {

struct RenderStats {
    int samplesPerPixel = 0;
    double elapsedSeconds = 0.0; // wall time of passes since the last reset
    IntegratorTimings timings;
    std::string deviceName;
    int validationMessages = 0;
    // The direction samplers' tables in use (nullptr for `bsdf`) and what setScene rebuilt or
    // reused since the integrator was created: the render report's "samplerTables".
    std::shared_ptr<const DirectionSamplerTables> samplerTables;
    SamplerTablesRebuilds samplerRebuilds;
    // What the last create/setScene/applyChanges rebuilt and uploaded (describeUpdate), and the
    // sums since the session was created.
    UpdateCounts lastUpdate;
    UpdateCounts totalUpdates;
};

class RenderSession {
public:
    // Creates the integrator chosen by options.device (Auto: Vulkan if a device can be created,
    // else an error unless the CPU tracer is available). Errors name what failed.
    static util::Result<std::unique_ptr<RenderSession>> create(const scene::Scene& scene,
                                                                const RenderOptions& options);
    ~RenderSession();

    // One pass (one sample per pixel), or less when the interrupt check stops it: then
    // samplesPerPixel() is unchanged and the next call resumes the pass (Integrator::renderPass).
    util::Status renderPass();
    // Polled between the pieces of a pass, from the thread that calls renderPass (the editor:
    // "quitting, or a newer job or a display request is waiting"). Kept for integrators that a
    // later setScene creates. The CPU tracer does not split passes and never calls it.
    void setInterruptCheck(InterruptCheck check);
    int samplesPerPixel() const;
    util::Result<util::ImageRGB> image();
    // With RenderOptions::lightGroups, the mean of each LightMix layer (lightGroups() order; they
    // sum to image()); without, an empty list.
    util::Result<std::vector<util::ImageRGB>> groupImages();
    // The light groups of the session's scene (names of groupImages()' layers).
    LightGroups lightGroups() const;
    RenderStats stats() const;
    const RenderOptions& options() const { return m_options; }

    // Replaces the scene (after an edit) and restarts accumulation. The BVH is rebuilt; an
    // integrator that can swap scenes keeps its device and rebuilds only the sampler tables the
    // edit invalidates (the CPU tracer: env change -> env + product tables, material edit -> that
    // material's, object move -> none); otherwise the integrator is recreated.
    util::Status setScene(const scene::Scene& scene);
    // Applies an edit: `scene` is the session's scene after `changes` (the editor's merged
    // change set since the last update). The BVH is kept, refitted or rebuilt as the changes
    // need (bvh_update.h) and the integrator updates only what they invalidate (a light drag:
    // the light buffer only). An integrator that cannot update in place is recreated.
    util::Status applyChanges(const scene::Scene& scene, const scene::ChangeSet& changes);
    void resetAccumulation();

private:
    RenderSession(RenderOptions options);
    RenderOptions m_options;
    // Counts the session's BVH work into `bvhCounts`, then records the integrator's uploads.
    void recordUpdate(UpdateCounts bvhCounts);
    std::unique_ptr<scene::Scene> m_scene;
    std::shared_ptr<const scene::Bvh> m_bvh;
    std::unique_ptr<Integrator> m_integrator;
    UpdateCounts m_lastUpdate, m_totalUpdates;
    InterruptCheck m_interrupt;
    double m_elapsed = 0.0;
};

} // namespace wavelit::render
