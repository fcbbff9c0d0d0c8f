#include "viewport/render_worker.h"

#include "viewport/tone_map.h"

#include "render/session/image_metrics.h"
#include "render/session/light_remix.h"
#include "scene/scene_io.h"

#include <QTimer>

#include <algorithm>
#include <cmath>

namespace wavelit::editor {
namespace {

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

void RenderWorker::wake() {
    m_shared->pendingRequests.fetch_sub(1);
    scheduleStep();
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
    if (!m_job.scene) return;
    if (wantDraft()) {
        draftStep();
        return;
    }
    if (auto status = m_full.sync([this] { return interrupted(); }); !status) {
        fail(toQString(status.error()));
        return;
    }
    if (!m_full.session || m_shared->cancel.load()) return; // cancelled while it was created
    if (m_maxSpp > 0 && m_full.session->samplesPerPixel() >= m_maxSpp) return; // idle until a new job

    const int before = m_full.session->samplesPerPixel();
    m_shared->passRunning.store(true);
    const util::Status status = m_full.session->renderPass();
    m_shared->passRunning.store(false);
    if (!status) {
        fail(toQString(status.error()));
        return;
    }
    const int spp = m_full.session->samplesPerPixel();
    if (spp == before) { // interrupted: handle the request, then resume the pass
        scheduleStep();
        return;
    }
    const bool first = m_publishedSpp < 0;
    const bool last = m_maxSpp > 0 && spp >= m_maxSpp;
    const bool due = m_sinceFrame.elapsed() >= kFrameIntervalMs &&
                     m_shared->framesInFlight.load() < kMaxFramesInFlight;
    if (first || last || due) publish();
    // The draft session is created once, right after the first full frame, so an edit's first
    // draft pays no pipeline compile (a new session compiles its own: 0.3 s to seconds).
    if (first && wantsDraftSession() && !m_draft.session)
        if (auto created = m_draft.sync([this] { return m_shared->cancel.load(); }); !created) {
            m_draftsEnabled = false;
            m_draft.reset();
            qWarning("wavelit: reduced-resolution drafts off: %s", qPrintable(toQString(created.error())));
        }
    if (!last) scheduleStep();
}

bool RenderWorker::wantsDraftSession() const {
    return m_draftsEnabled && !m_job.options.lightGroups && m_job.options.width >= 2 * kDraftDivisor &&
           m_job.options.height >= 2 * kDraftDivisor;
}

bool RenderWorker::wantDraft() const {
    if (!wantsDraftSession()) return false;
    // While a drag lasts (until its draft holds kDraftMaxSpp), and once per edit before the
    // full session's first frame (an edit's first frame comes from the draft).
    if (m_shared->interactive.load()) return m_draftSpp < kDraftMaxSpp;
    return m_job.changes.has_value() && !m_draftShown && m_publishedSpp < 0;
}

render::RenderOptions RenderWorker::draftOptions(const render::RenderOptions& full) {
    render::RenderOptions options = full;
    options.width = std::max(1, (full.width + kDraftDivisor - 1) / kDraftDivisor);
    options.height = std::max(1, (full.height + kDraftDivisor - 1) / kDraftDivisor);
    // Sampler tables are what an environment or material edit rebuilds (the product tables:
    // seconds; even MIS rebuilds its environment table on a rotation): the draft samples the
    // BSDF, which needs none, so no edit rebuilds anything but the BVH refit and the buffers it
    // touches. Unbiased, noisier under a small bright sun: a draft is a draft.
    options.sampler = render::SamplerKind::Bsdf;
    options.lightGroups = false;
    return options;
}

void RenderWorker::draftStep() {
    // A draft that cannot render (no device for a second session, a sampler the device lacks)
    // turns drafts off; the full session still reports real problems with the scene.
    auto disable = [this](const QString& why) {
        m_draftsEnabled = false;
        m_draft.reset();
        qWarning("wavelit: reduced-resolution drafts off: %s", qPrintable(why));
        scheduleStep();
    };
    // A draft pass is short (1/16 of the pixels): it is not interrupted by the next edit, else a
    // drag sending an edit per mouse move would restart it forever and show nothing.
    if (auto status = m_draft.sync([this] { return m_shared->cancel.load(); }); !status)
        return disable(toQString(status.error()));
    const int before = m_draft.session->samplesPerPixel();
    m_shared->passRunning.store(true);
    const util::Status status = m_draft.session->renderPass();
    m_shared->passRunning.store(false);
    if (!status) return disable(toQString(status.error()));
    m_draftSpp = m_draft.session->samplesPerPixel();
    if (m_draftSpp != before) publishDraft();
    scheduleStep();
}

void RenderWorker::publishDraft() {
    auto image = m_draft.session->image();
    if (!image) return;
    const util::ImageRGB& small = image.value();
    // Nearest-pixel enlargement to the render size: the viewport's image keeps its size (picking,
    // gizmos) and shows the draft's pixels as blocks, not as a smoothed fake of the full image.
    const int w = m_job.options.width, h = m_job.options.height;
    util::ImageRGB large(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            large.at(x, y) = small.at(std::min(x * small.width / w, small.width - 1),
                                      std::min(y * small.height / h, small.height - 1));
    const render::RenderStats stats = m_draft.session->stats();
    RenderFrame frame;
    frame.kind = RenderFrame::Kind::Draft;
    frame.image = std::make_shared<const util::ImageRGB>(std::move(large));
    frame.samplesPerPixel = stats.samplesPerPixel;
    frame.elapsedSeconds = stats.elapsedSeconds;
    frame.deviceName = QString::fromStdString(stats.deviceName);
    frame.validationMessages = stats.validationMessages;
    frame.lastUpdate = QStringLiteral("draft %1x%2: %3")
                           .arg(small.width)
                           .arg(small.height)
                           .arg(QString::fromStdString(render::describeUpdate(stats.lastUpdate)));
    frame.generation = m_generation;
    frame.displayExposureEv = m_shared->exposureEv.load();
    frame.display = toneMap(*frame.image, frame.displayExposureEv);
    m_draftShown = true;
    m_shared->framesInFlight.fetch_add(1);
    emit frameReady(std::move(frame)); // not m_lastFrame: that is the full session's
}

bool RenderWorker::tryRemix(const RenderJob& job) {
    if (!job.options.lightGroups || !m_full.session || m_full.update || !m_renderedScene || !job.scene ||
        !sameSessionOptions(m_full.options, job.options))
        return false;
    auto weights = render::remixWeights(*m_renderedScene, *job.scene);
    if (!weights) return false;
    m_weights = std::move(*weights);
    m_generation = job.generation;
    m_maxSpp = job.maxSamplesPerPixel;
    m_remixed = true;
    m_job = job;
    // The next display frame: now, from the samples so far (none yet: the first pass publishes);
    // its status says what it cost (layer read-back, recombination, tone mapping).
    if (m_full.session->samplesPerPixel() > 0) {
        m_remixTimer.start();
        publish();
        m_remixTimer.invalidate();
    }
    return true;
}

util::Result<util::ImageRGB> RenderWorker::sessionImage() {
    if (!m_full.options.lightGroups) return m_full.session->image();
    auto layers = m_full.session->groupImages();
    if (!layers) return layers.error();
    m_lastLayers = std::make_shared<const std::vector<util::ImageRGB>>(std::move(*layers)); // for A/B
    return render::mixGroupLayers(*m_lastLayers, m_weights);
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
        m_full.reset();
        m_draft.reset();
        m_job = RenderJob{};
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
    // Both sessions take the job when they render next (session_slot.h). An edit of the scene a
    // session holds updates only what it changed; anything else (a newly opened scene, a session
    // that missed a job) swaps in the whole scene. (LightMix sessions hold remixBaseScene, which
    // the change set does not lead from.)
    m_full.queue(rendered, job.options, job.generation, job.changes, job.baseGeneration, !job.options.lightGroups);
    if (m_draftsEnabled && !job.options.lightGroups)
        m_draft.queue(job.scene, draftOptions(job.options), job.generation, job.changes, job.baseGeneration, true);
    m_draftShown = false;
    m_draftSpp = 0;
    m_job = std::move(job);
    return true;
}

void RenderWorker::publish() {
    auto image = sessionImage();
    if (!image) {
        fail(toQString(image.error()));
        return;
    }
    const render::RenderStats stats = m_full.session->stats();
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
    if (m_full.options.lightGroups) {
        frame.layers = std::move(m_lastLayers);
        frame.layersScene = m_renderedScene;
    }
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
    m_full.reset();
    m_draft.reset();
    m_renderedScene.reset();
    m_lastFrame = RenderFrame{};
    emit failed(message, m_generation);
}

} // namespace wavelit::editor
