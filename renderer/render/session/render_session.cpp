// RenderSession: scene copy + BVH + one integrator picked by RenderOptions::device.
// Auto prefers Vulkan and falls back to the CPU reference tracer only when the Vulkan tracer
// cannot serve the options (no usable device, a sampler not on the GPU yet: errors naming no file);
// a broken shader or a request beyond the device's limits (render_limits.h) is reported, never
// hidden behind a silent CPU fallback (architecture.md §9: no silent
// fallbacks that draw a different image).
#include "render/session/render_session.h"

#include "render/session/bvh_update.h"
#include "render/session/integrator_factory.h"
#include "render/session/light_groups.h"
#include "render/gpu/render_limits.h"
#include "scene/bvh.h"
#include "util/log.h"
#include "util/timer.h"

namespace wavelit::render {
namespace {

// The CPU tracer's image buffers must fit the machine's memory (render_limits.h): refused up
// front instead of the process being killed while it allocates.
util::Result<std::unique_ptr<Integrator>> makeCpuIntegrator(std::shared_ptr<const scene::Scene> scene,
                                                            std::shared_ptr<const scene::Bvh> bvh,
                                                            const RenderOptions& options) {
    const size_t groups = options.lightGroups ? lightGroupsOf(*scene).size() : 0;
    if (auto fits = checkCpuImageMemory(options.width, options.height, physicalMemoryBytes(), groups);
        !fits)
        return fits.error();
    return createCpuPathTracer(std::move(scene), std::move(bvh), options);
}

util::Result<std::unique_ptr<Integrator>> makeIntegrator(std::shared_ptr<const scene::Scene> scene,
                                                         std::shared_ptr<const scene::Bvh> bvh,
                                                         const RenderOptions& options) {
    switch (options.device) {
    case DeviceChoice::Vulkan:
        return createGpuPathTracer(scene, bvh, options);
    case DeviceChoice::Cpu:
        return makeCpuIntegrator(scene, bvh, options);
    case DeviceChoice::Auto:
        break;
    }
    auto gpu = createGpuPathTracer(scene, bvh, options);
    // A request beyond the device's limits (render_limits.h: ErrorKind::Invalid) is reported with
    // what to change, not moved to the CPU tracer at a size the device could not hold.
    if (gpu || !gpu.error().file.empty() || gpu.error().kind == util::ErrorKind::Invalid)
        return gpu;
    util::logWarning("Vulkan path tracer unavailable (" + gpu.error().message() +
                     "); rendering on the CPU reference tracer");
    return makeCpuIntegrator(scene, bvh, options);
}

} // namespace

RenderSession::RenderSession(RenderOptions options) : m_options(std::move(options)) {}
RenderSession::~RenderSession() = default;

util::Result<std::unique_ptr<RenderSession>> RenderSession::create(const scene::Scene& scene,
                                                                   const RenderOptions& options) {
    if (options.width <= 0 || options.height <= 0)
        return util::makeError(util::ErrorKind::Usage, "",
                               "image size must be positive, got " + std::to_string(options.width) +
                                   "x" + std::to_string(options.height));
    std::unique_ptr<RenderSession> session(new RenderSession(options));
    auto status = session->setScene(scene);
    if (!status)
        return status.error();
    return session;
}

util::Status RenderSession::setScene(const scene::Scene& scene) {
    auto copy = std::make_shared<const scene::Scene>(scene);
    auto bvh = std::make_shared<const scene::Bvh>(scene::buildBvh(*copy));
    UpdateCounts bvhCounts;
    bvhCounts.bvhBuilds = 1;
    // Keep the device and compiled pipelines when the integrator can swap scenes (pipeline
    // creation costs 0.1-0.3 s on lavapipe: too slow for every edit).
    if (m_integrator) {
        auto swapped = m_integrator->setScene(copy, bvh);
        if (swapped) {
            m_scene = std::make_unique<scene::Scene>(scene);
            m_bvh = std::move(bvh);
            m_elapsed = 0.0;
            recordUpdate(bvhCounts);
            return swapped;
        }
        if (swapped.error().kind != util::ErrorKind::Unsupported || !swapped.error().file.empty() ||
            !swapped.error().where.empty())
            return swapped; // a real problem with the new scene (e.g. unknown BRDF)
    }
    m_integrator.reset(); // release the old device before creating a new one
    auto integrator = makeIntegrator(copy, bvh, m_options);
    if (!integrator)
        return integrator.error();
    m_integrator = std::move(integrator.value());
    m_integrator->setInterruptCheck(m_interrupt);
    m_scene = std::make_unique<scene::Scene>(scene);
    m_bvh = std::move(bvh);
    m_elapsed = 0.0;
    recordUpdate(bvhCounts);
    return util::okStatus();
}

util::Status RenderSession::applyChanges(const scene::Scene& scene, const scene::ChangeSet& changes) {
    if (!m_integrator || !m_bvh)
        return setScene(scene);
    auto copy = std::make_shared<const scene::Scene>(scene);
    UpdateCounts bvhCounts;
    auto bvh = updateBvh(m_bvh, *copy, changes, bvhCounts);
    auto status = m_integrator->applyChanges(copy, bvh, changes);
    if (!status) {
        if (status.error().kind != util::ErrorKind::Unsupported || !status.error().file.empty() ||
            !status.error().where.empty())
            return status;
        return setScene(scene); // the integrator cannot swap scenes: recreate it
    }
    m_scene = std::make_unique<scene::Scene>(scene);
    m_bvh = std::move(bvh);
    m_elapsed = 0.0;
    recordUpdate(bvhCounts);
    return util::okStatus();
}

void RenderSession::recordUpdate(UpdateCounts counts) {
    counts += m_integrator->lastUpdate();
    m_lastUpdate = counts;
    m_totalUpdates += counts;
}

util::Status RenderSession::renderPass() {
    if (!m_integrator)
        return util::makeError(util::ErrorKind::Invalid, "", "render session has no integrator");
    util::Timer timer;
    auto status = m_integrator->renderPass();
    m_elapsed += timer.seconds();
    return status;
}

void RenderSession::setInterruptCheck(InterruptCheck check) {
    m_interrupt = std::move(check);
    if (m_integrator)
        m_integrator->setInterruptCheck(m_interrupt);
}

int RenderSession::samplesPerPixel() const {
    return m_integrator ? m_integrator->samplesPerPixel() : 0;
}

util::Result<util::ImageRGB> RenderSession::image() {
    if (!m_integrator)
        return util::makeError(util::ErrorKind::Invalid, "", "render session has no integrator");
    return m_integrator->image();
}

util::Result<std::vector<util::ImageRGB>> RenderSession::groupImages() {
    if (!m_integrator)
        return util::makeError(util::ErrorKind::Invalid, "", "render session has no integrator");
    if (!m_options.lightGroups) return std::vector<util::ImageRGB>{};
    return m_integrator->groupImages();
}

LightGroups RenderSession::lightGroups() const {
    return m_scene ? lightGroupsOf(*m_scene) : LightGroups{};
}

RenderStats RenderSession::stats() const {
    RenderStats s;
    if (!m_integrator)
        return s;
    s.samplesPerPixel = m_integrator->samplesPerPixel();
    s.elapsedSeconds = m_elapsed;
    s.timings = m_integrator->timings();
    s.deviceName = m_integrator->deviceName();
    s.validationMessages = m_integrator->validationMessageCount();
    s.samplerTables = m_integrator->samplerTables();
    s.samplerRebuilds = m_integrator->samplerRebuilds();
    s.lastUpdate = m_lastUpdate;
    s.totalUpdates = m_totalUpdates;
    return s;
}

void RenderSession::resetAccumulation() {
    if (m_integrator)
        m_integrator->resetAccumulation();
    m_elapsed = 0.0;
}

} // namespace wavelit::render
