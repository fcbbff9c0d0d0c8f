#include "viewport/render_worker.h"

#include "viewport/tone_map.h"

#include "render/session/image_metrics.h"
#include "render/session/light_remix.h"
#include "scene/scene_io.h"

#include <QTimer>

#include <cmath>

namespace wavelit::editor {
namespace {

// A session can take a new scene (setScene) only when everything it was created with is the same.
bool sameSessionOptions(const render::RenderOptions& a, const render::RenderOptions& b) {
    return a.width == b.width && a.height == b.height && a.bounces == b.bounces &&
           a.seed == b.seed && a.device == b.device && a.sampler == b.sampler &&
           a.vulkanDevice == b.vulkanDevice && a.validation == b.validation &&
           a.lightGroups == b.lightGroups;
}

QString toQString(const util::Error& error) { return QString::fromStdString(error.message()); }

// True when an edit left an asset unloaded (the registry's setter drops a mesh or map whose
// path changed).
bool missingAssets(const scene::Scene& scene) {
    for (const auto& object : scene.objects)
        if (!object.mesh) return true;
    return !scene.lighting.environment.path.empty() && !scene.lighting.environment.image;
}

} // namespace

RenderWorker::RenderWorker(std::shared_ptr<RenderShared> shared) : m_shared(std::move(shared)) {}

RenderWorker::~RenderWorker() = default;

void RenderWorker::submit(RenderJob job) {
    m_shared->pendingRequests.fetch_sub(1);
    // Newest wins, but an edit replacing an edit not yet started carries both: the merged change
    // set leads from the older one's base scene to the newest (newest value per property wins).
    if (m_pending && job.changes) {
        if (m_pending->changes && m_pending->scene) {
            scene::ChangeSet merged = std::move(*m_pending->changes);
            merged.merge(*job.changes);
            job.changes = std::move(merged);
            job.baseGeneration = m_pending->baseGeneration;
        } else {
            job.changes.reset(); // the pending job was a whole scene: so is this one
        }
    }
    m_pending = std::move(job);
    scheduleStep();
}

void RenderWorker::retoneMap() {
    m_shared->pendingRequests.fetch_sub(1);
    m_shared->retoneMapQueued.store(false);
    if (m_shared->cancel.load() || !m_lastFrame.image || m_lastFrame.generation != m_generation)
        return;
    const float ev = m_shared->exposureEv.load();
    if (ev == m_lastFrame.displayExposureEv) return;
    RenderFrame frame = m_lastFrame;
    frame.display = toneMap(*frame.image, ev);
    frame.displayExposureEv = ev;
    emitFrame(std::move(frame));
}

bool RenderWorker::interrupted() const {
    return m_shared->cancel.load() || m_shared->pendingRequests.load() > 0;
}

void RenderWorker::scheduleStep() {
    if (m_stepScheduled) return;
    m_stepScheduled = true;
    QTimer::singleShot(0, this, [this] {
        m_stepScheduled = false;
        step();
    });
}

void RenderWorker::step() {
    if (m_shared->cancel.load()) return;
    if (m_pending && !startPendingJob()) return;
    if (!m_session) return;
    if (m_maxSpp > 0 && m_session->samplesPerPixel() >= m_maxSpp) return; // idle until a new job

    const int before = m_session->samplesPerPixel();
    m_shared->passRunning.store(true);
    const util::Status status = m_session->renderPass();
    m_shared->passRunning.store(false);
    if (!status) {
        fail(toQString(status.error()));
        return;
    }
    const int spp = m_session->samplesPerPixel();
    if (spp == before) { // interrupted: handle the request, then resume the pass
        scheduleStep();
        return;
    }
    const bool first = m_publishedSpp < 0;
    const bool last = m_maxSpp > 0 && spp >= m_maxSpp;
    const bool due = m_sinceFrame.elapsed() >= kFrameIntervalMs &&
                     m_shared->framesInFlight.load() < kMaxFramesInFlight;
    if (first || last || due) publish();
    if (!last) scheduleStep();
}

bool RenderWorker::tryRemix(const RenderJob& job) {
    if (!job.options.lightGroups || !m_session || !m_renderedScene || !job.scene ||
        !sameSessionOptions(m_sessionOptions, job.options))
        return false;
    auto weights = render::remixWeights(*m_renderedScene, *job.scene);
    if (!weights) return false;
    m_weights = std::move(*weights);
    m_generation = job.generation;
    m_maxSpp = job.maxSamplesPerPixel;
    m_remixed = true;
    // The next display frame: now, from the samples so far (none yet: the first pass publishes);
    // its status says what it cost (layer read-back, recombination, tone mapping).
    if (m_session->samplesPerPixel() > 0) {
        m_remixTimer.start();
        publish();
        m_remixTimer.invalidate();
    }
    return true;
}

util::Result<util::ImageRGB> RenderWorker::sessionImage() {
    if (!m_sessionOptions.lightGroups) return m_session->image();
    auto layers = m_session->groupImages();
    if (!layers) return layers.error();
    return render::mixGroupLayers(*layers, m_weights);
}

bool RenderWorker::startPendingJob() {
    RenderJob job = std::move(*m_pending);
    m_pending.reset();
    if (tryRemix(job)) return true;
    m_remixed = false;
    m_generation = job.generation;
    m_maxSpp = job.maxSamplesPerPixel;
    m_publishedSpp = -1;
    m_lastFrame = RenderFrame{};
    if (!job.scene) {
        m_session.reset();
        m_sessionGeneration = 0;
        return false;
    }
    if (missingAssets(*job.scene)) {
        auto completed = std::make_shared<scene::Scene>(*job.scene);
        if (auto status = scene::loadAssets(*completed, job.scenePath); !status) {
            fail(toQString(status.error()));
            return false;
        }
        job.scene = std::move(completed);
    }
    // LightMix: the session renders every light unmuted (a muted light's layer stays, weight 0).
    std::shared_ptr<const scene::Scene> rendered = job.scene;
    if (job.options.lightGroups) {
        rendered = std::make_shared<const scene::Scene>(render::remixBaseScene(*job.scene));
        m_weights = render::remixWeights(*rendered, *job.scene).value_or(std::vector<glm::vec3>{});
    }
    m_renderedScene = job.options.lightGroups ? rendered : nullptr;
    if (m_session && sameSessionOptions(m_sessionOptions, job.options)) {
        // An edit of the scene the session holds updates only what it changed; anything else
        // (a newly opened scene, a session that missed a job) swaps in the whole scene.
        // (LightMix sessions hold remixBaseScene, which the change set does not lead from.)
        const bool incremental = job.changes && m_sessionGeneration != 0 &&
                                 m_sessionGeneration == job.baseGeneration &&
                                 !job.options.lightGroups;
        const util::Status status = incremental ? m_session->applyChanges(*job.scene, *job.changes)
                                                : m_session->setScene(*rendered);
        if (!status) {
            fail(toQString(status.error()));
            return false;
        }
        m_sessionGeneration = job.generation;
        return true;
    }
    m_session.reset(); // release the old device before creating the next one
    auto created = render::RenderSession::create(*rendered, job.options);
    if (!created) {
        fail(toQString(created.error()));
        return false;
    }
    m_session = std::move(created.value());
    m_session->setInterruptCheck([this] { return interrupted(); });
    m_sessionOptions = job.options;
    m_sessionGeneration = job.generation;
    return true;
}

void RenderWorker::publish() {
    auto image = sessionImage();
    if (!image) {
        fail(toQString(image.error()));
        return;
    }
    const render::RenderStats stats = m_session->stats();
    RenderFrame frame;
    frame.image = std::make_shared<const util::ImageRGB>(std::move(image.value()));
    frame.samplesPerPixel = stats.samplesPerPixel;
    frame.elapsedSeconds = stats.elapsedSeconds;
    frame.deviceName = QString::fromStdString(stats.deviceName);
    frame.validationMessages = stats.validationMessages;
    frame.lastUpdate = QString::fromStdString(render::describeUpdate(stats.lastUpdate));
    frame.generation = m_generation;
    frame.last = m_maxSpp > 0 && frame.samplesPerPixel >= m_maxSpp;
    // render_frame.h: the error of I_n estimated from the previous frame I_m of this generation.
    const RenderFrame& previous = m_lastFrame;
    const int m = previous.samplesPerPixel, n = frame.samplesPerPixel;
    if (previous.image && previous.generation == m_generation && previous.kind == RenderFrame::Kind::PathTraced &&
        m > 0 && n > m && previous.image->width == frame.image->width &&
        previous.image->height == frame.image->height)
        frame.estimatedRelError =
            std::sqrt(render::relativeMse(*previous.image, *frame.image) * double(m) / double(n - m));
    frame.displayExposureEv = m_shared->exposureEv.load();
    frame.display = toneMap(*frame.image, frame.displayExposureEv);
    if (m_remixed)
        frame.lastUpdate = m_remixTimer.isValid()
                               ? QStringLiteral("remixed: no restart (frame in %1 ms)")
                                     .arg(double(m_remixTimer.nsecsElapsed()) * 1e-6, 0, 'f', 2)
                               : QStringLiteral("remixed: no restart");
    m_publishedSpp = frame.samplesPerPixel;
    m_sinceFrame.restart();
    emitFrame(std::move(frame));
}

void RenderWorker::emitFrame(RenderFrame frame) {
    m_lastFrame = frame; // shares the images
    m_shared->framesInFlight.fetch_add(1);
    emit frameReady(std::move(frame));
}

void RenderWorker::fail(const QString& message) {
    // A failed session is in an unknown state (device lost, bad scene): drop it; the next job
    // creates a fresh one.
    m_session.reset();
    m_sessionGeneration = 0;
    m_renderedScene.reset();
    m_lastFrame = RenderFrame{};
    emit failed(message, m_generation);
}

} // namespace wavelit::editor
