#include "viewport/render_controller.h"

#include "viewport/finishing_threads.h"
#include "viewport/relight_worker.h"
#include "viewport/render_worker.h"

namespace wavelit::editor {

RenderController::RenderController(RenderSettings settings, QObject* parent)
    : QObject(parent), m_settings(settings), m_shared(std::make_shared<RenderShared>()) {
    qRegisterMetaType<RenderFrame>();
    qRegisterMetaType<RenderJob>();
    m_thread = std::make_unique<QThread>();
    m_thread->setObjectName("wavelit-render");
    m_worker = new RenderWorker(m_shared);
    m_worker->moveToThread(m_thread.get());
    connect(m_thread.get(), &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &RenderWorker::frameReady, this, &RenderController::onFrame,
            Qt::QueuedConnection);
    connect(m_worker, &RenderWorker::failed, this, &RenderController::onFailed,
            Qt::QueuedConnection);
    m_thread->start();
    if (m_settings.relightPreview) {
        m_relightThread = std::make_unique<QThread>();
        m_relightThread->setObjectName("wavelit-relight");
        m_relight = new RelightWorker(m_shared);
        m_relight->moveToThread(m_relightThread.get());
        connect(m_relightThread.get(), &QThread::finished, m_relight, &QObject::deleteLater);
        connect(m_relight, &RelightWorker::frameReady, this, &RenderController::onRelightFrame,
                Qt::QueuedConnection);
        connect(m_relight, &RelightWorker::skipped, this, [this] { m_relightFollows = false; },
                Qt::QueuedConnection);
        m_relightThread->start();
    }
}

RenderController::~RenderController() { shutdown(); }

void RenderController::shutdown() {
    cancel();
    // The worker's step returns at the next piece boundary; the loop then quits and `finished`
    // deletes the worker (and with it the session and its device) on the render thread. The
    // workers go with their threads, so they are not reached from here any more.
    m_worker = nullptr;
    m_relight = nullptr;
    for (std::unique_ptr<QThread>* thread : {&m_thread, &m_relightThread})
        if (*thread) (*thread)->quit();
    // Both were told to quit first, and share one deadline.
    const QDeadlineTimer deadline(kJoinMs);
    for (std::unique_ptr<QThread>* thread : {&m_thread, &m_relightThread})
        joinOrLetFinish(std::move(*thread), deadline);
}

void RenderController::render(std::shared_ptr<const scene::Scene> scene, const QString& scenePath) {
    RenderJob job;
    job.scene = std::move(scene);
    job.scenePath = scenePath.toStdString();
    submit(std::move(job));
}

void RenderController::renderEdit(std::shared_ptr<const scene::Scene> scene, const QString& scenePath,
                                  const scene::ChangeSet& changes) {
    RenderJob job;
    job.scene = std::move(scene);
    job.scenePath = scenePath.toStdString();
    job.changes = changes;
    job.baseGeneration = m_generation; // the job whose scene `changes` starts from
    submit(std::move(job));
}

void RenderController::submit(RenderJob job) {
    if (m_shared->cancel.load()) return;
    job.generation = ++m_generation;
    job.maxSamplesPerPixel = m_settings.maxSamplesPerPixel;
    if (job.scene) {
        job.options.width = m_settings.width > 0 ? m_settings.width : job.scene->render.width;
        job.options.height = m_settings.height > 0 ? m_settings.height : job.scene->render.height;
        job.options.bounces = job.scene->render.bounces;
    }
    job.options.device = m_settings.device;
    job.options.sampler = m_settings.sampler;
    job.options.validation = m_settings.validation;
    job.options.lightGroups = m_settings.lightMix;
    m_latest = RenderFrame{};
    m_latestPreview = RenderFrame{};
    if (!job.changes) { // a new scene: nothing of the old one stays
        m_displayed = RenderFrame{};
        m_sceneGeneration = job.generation;
    }
    m_sinceEdit.start();
    if (m_relight)
        QMetaObject::invokeMethod(m_relight, [worker = m_relight, job]() mutable { worker->submit(std::move(job)); },
                                  Qt::QueuedConnection);
    // Counted before it is queued: the running pass stops at its next piece to take it.
    m_shared->pendingRequests.fetch_add(1);
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, job = std::move(job)]() mutable { worker->submit(std::move(job)); },
        Qt::QueuedConnection);
}

void RenderController::cancel() { m_shared->cancel.store(true); }

void RenderController::setExposure(float ev) {
    if (ev == m_exposureEv || m_shared->cancel.load()) return;
    m_exposureEv = ev;
    m_shared->exposureEv.store(ev);
    // One queued retoneMap at a time: it reads the newest exposure when it runs.
    if (m_shared->retoneMapQueued.exchange(true)) return;
    m_shared->pendingRequests.fetch_add(1);
    QMetaObject::invokeMethod(m_worker, [worker = m_worker] { worker->retoneMap(); },
                              Qt::QueuedConnection);
}

void RenderController::selectionChanged(std::optional<scene::EntityRef> ref) {
    if (!m_relight || !ref || ref->kind != scene::EntityKind::Object) return;
    QMetaObject::invokeMethod(m_relight, [worker = m_relight, id = ref->id] { worker->prepareObject(id); },
                              Qt::QueuedConnection);
}

bool RenderController::relightFieldReady(scene::EntityId object) const {
    bool ready = false;
    if (m_relight)
        QMetaObject::invokeMethod(m_relight, [&ready, worker = m_relight, object] { ready = worker->fieldReady(object); },
                                  Qt::BlockingQueuedConnection);
    return ready;
}

void RenderController::setInteractive(bool active) {
    // The only call that does not stop at the cancel flag: after shutdown() no worker is left.
    if (m_shared->interactive.exchange(active) == active || active || !m_worker) return;
    // The drag ended: a worker that is idle (drafts are done) must wake up for the full session.
    m_shared->pendingRequests.fetch_add(1);
    QMetaObject::invokeMethod(m_worker, [worker = m_worker] { worker->wake(); }, Qt::QueuedConnection);
}

bool RenderController::passRunning() const { return m_shared->passRunning.load(); }

void RenderController::onFrame(RenderFrame frame) {
    m_shared->framesInFlight.fetch_sub(1);
    if (m_shared->cancel.load()) return;
    if (frame.kind == RenderFrame::Kind::Draft) {
        // Drafts of an edit the UI has already moved past are still the newest image during a
        // drag (display() keeps generations increasing). A draft never replaces the full-size
        // frame of its own edit, nor its preview, nor during a drag a preview that follows it.
        const bool fullShown = m_displayed.image && m_displayed.generation == frame.generation &&
                               m_displayed.kind == RenderFrame::Kind::PathTraced;
        const bool previewFollows = m_displayed.image && m_displayed.kind == RenderFrame::Kind::Relight &&
                                    (m_displayed.generation == frame.generation ||
                                     (m_relightFollows && m_shared->interactive.load()));
        if (!fullShown && !previewFollows) display(std::move(frame));
        return;
    }
    if (frame.generation != m_generation) return;
    m_latest = frame;
    emit frameReady(m_latest);
    // Within one generation the preview stays until the tracer's estimate is as good (header).
    const bool previewShown = m_displayed.kind == RenderFrame::Kind::Relight &&
                              m_displayed.generation == frame.generation;
    // An exposure change re-maps the tracer's frame; the preview on screen would keep the old one.
    const bool handOver = frame.last || frame.displayExposureEv != m_displayed.displayExposureEv ||
                          (frame.estimatedRelError >= 0.0 && frame.estimatedRelError <= kPreviewRelError);
    if (previewShown && !handOver) return;
    display(std::move(frame));
}

void RenderController::onRelightFrame(RenderFrame frame) {
    if (m_shared->cancel.load() || frame.generation > m_generation) return;
    m_relightFollows = true;
    if (frame.generation == m_generation) m_latestPreview = frame;
    // A preview of a generation the full-size tracer has handed over to (its estimated error is
    // as good, or it stopped) is never better; it is better than a draft of it, and than a
    // tracer frame that merely came first (during a held drag the render thread goes to full
    // size after kDraftMaxSpp draft samples, and its first frame can beat a first answer).
    const bool handedOver = m_displayed.last ||
                            (m_displayed.estimatedRelError >= 0.0 && m_displayed.estimatedRelError <= kPreviewRelError);
    if (frame.generation == m_displayed.generation && m_displayed.kind == RenderFrame::Kind::PathTraced &&
        m_displayed.image && handedOver)
        return;
    display(std::move(frame));
}

void RenderController::display(RenderFrame frame) {
    if (frame.generation < m_sceneGeneration) return; // of a scene no longer open
    if (m_displayed.image && frame.generation < m_displayed.generation) return; // older than shown
    frame.msSinceEdit = frame.generation == m_generation && m_sinceEdit.isValid()
                            ? double(m_sinceEdit.nsecsElapsed()) * 1e-6
                            : -1.0;
    m_displayed = std::move(frame);
    ++m_framesDisplayed;
    emit displayFrame(m_displayed);
}

void RenderController::onFailed(const QString& message, quint64 generation) {
    if (generation != m_generation) return;
    emit failed(message);
}

} // namespace wavelit::editor
