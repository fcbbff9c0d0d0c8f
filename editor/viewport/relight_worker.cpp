#include "viewport/relight_worker.h"

#include "viewport/render_worker.h"
#include "viewport/tone_map.h"

#include "relight/edit_rules.h"
#include "relight/sphere_level.h"

#include <QElapsedTimer>

#include <algorithm>

namespace wavelit::editor {
namespace {

enum class Handling { Exact, FirstAnswer, Rebuild };

// What the preview does with an edit (header; docs/relighting.md §3 says what each edit costs).
Handling handlingOf(const scene::ChangeSet& changes) {
    Handling handling = Handling::Exact;
    for (const scene::Edit& edit : changes.edits()) {
        const auto* p = std::get_if<scene::PropertyEdit>(&edit);
        if (!p) return Handling::Rebuild; // entities added or removed: everything changes
        switch (p->entity.kind) {
        case scene::EntityKind::Camera:
        case scene::EntityKind::Render: return Handling::Rebuild; // every point, or another size
        case scene::EntityKind::Object:
            if (p->property == "mesh") return Handling::Rebuild; // loaded on the render thread
            if (p->property != "name") handling = Handling::FirstAnswer;
            break;
        case scene::EntityKind::Material:
            // Colour and emission are mixed in when the image is summed (no per-point work for
            // the linear and affine BRDFs of plugins/): exact at once, like a light's power.
            if (p->property != "baseColor" && p->property != "emission" && p->property != "name")
                handling = Handling::FirstAnswer;
            break;
        default: break; // environment, lights: the full update is tens of ms (§7.0a)
        }
    }
    return handling;
}

bool assetsLoaded(const scene::Scene& scene) {
    for (const auto& object : scene.objects)
        if (!object.mesh) return false;
    return scene.lighting.environment.path.empty() || scene.lighting.environment.image;
}

QString kiB(size_t bytes) { return QString::number(double(bytes) / 1024.0, 'f', 0) + QStringLiteral(" KiB"); }

// The edit's kind for the status label, with the method when there is one ("object (shadowField)").
QString kindOf(const relight::EditSummary& summary) {
    const QString kind = QString::fromStdString(summary.kind);
    return summary.method.empty() ? kind
                                  : QStringLiteral("%1 (%2)").arg(kind, QString::fromStdString(summary.method));
}


} // namespace

relight::ShadowFieldSettings RelightWorker::fieldDragSettings() {
    relight::ShadowFieldSettings settings; // the field of docs/relighting.md §7.0e
    settings.reuseOwnStates = true;        // the moved object's own points without rays (§7.0j)
    settings.carriedLobeCut = 2.0f;        // their narrow lobes within two caps (§7.0k)
    return settings;
}

relight::RelightSettings RelightWorker::previewSettings(const scene::Scene& scene, int width, int height) {
    relight::RelightSettings settings;
    // One point per render pixel up to kMaxPreviewPoints per side, the aspect kept.
    const double shrink = std::min(1.0, double(kMaxPreviewPoints) / double(std::max(width, height)));
    settings.width = std::max(1, int(double(width) * shrink + 0.5));
    settings.height = std::max(1, int(double(height) * shrink + 0.5));
    settings.level = relight::chooseSphereLevel(scene).level;
    return settings;
}

RelightWorker::RelightWorker(std::shared_ptr<RenderShared> shared) : m_shared(std::move(shared)) {
    m_rebuildTimer = new QTimer(this);
    m_rebuildTimer->setSingleShot(true);
    m_rebuildTimer->setInterval(kRebuildQuietMs);
    connect(m_rebuildTimer, &QTimer::timeout, this, &RelightWorker::rebuild);
    m_fineTimer = new QTimer(this);
    m_fineTimer->setSingleShot(true);
    m_fineTimer->setInterval(kFinePauseMs);
    connect(m_fineTimer, &QTimer::timeout, this, &RelightWorker::refine);
}

RelightWorker::~RelightWorker() = default;

bool RelightWorker::cancelled() const { return m_shared->cancel.load(); }

void RelightWorker::submit(RenderJob job) {
    // Newest wins; an edit replacing one not yet started carries both (render_worker.h).
    if (m_pending && job.changes) {
        if (m_pending->changes && m_pending->scene) {
            scene::ChangeSet merged = std::move(*m_pending->changes);
            merged.merge(*job.changes);
            job.changes = std::move(merged);
            job.baseGeneration = m_pending->baseGeneration;
        } else {
            job.changes.reset();
        }
    }
    m_pending = std::move(job);
    if (m_stepScheduled) return;
    m_stepScheduled = true;
    QTimer::singleShot(0, this, [this] {
        m_stepScheduled = false;
        step();
    });
}

void RelightWorker::prepareObject(scene::EntityId object) {
    if (cancelled() || m_pending || !m_preview || m_preview->finePending()) return;
    const auto& objects = m_preview->fine().scene().objects;
    if (const size_t j = relight::indexOf(objects, object); j < objects.size()) m_preview->prepareFieldDrag(j);
}

bool RelightWorker::fieldReady(scene::EntityId object) {
    if (!m_preview) return false;
    const auto& objects = m_preview->fine().scene().objects;
    const size_t j = relight::indexOf(objects, object);
    return j < objects.size() && m_preview->fieldDragReady(j);
}

void RelightWorker::drop(quint64 generation) {
    if (m_preview)
        if (auto kept = m_preview->keptField()) m_keptField = std::move(kept);
    m_preview.reset();
    m_previewGeneration = 0;
    m_fineTimer->stop();
    emit skipped(generation);
}

void RelightWorker::step() {
    if (cancelled() || !m_pending) return;
    RenderJob job = std::move(*m_pending);
    m_pending.reset();
    m_latestScene = job.scene;
    m_latestGeneration = job.generation;
    m_width = job.options.width;
    m_height = job.options.height;
    if (!job.scene || !assetsLoaded(*job.scene) || job.options.width <= 0 || job.options.height <= 0) {
        drop(job.generation); // nothing to preview (the render thread loads dropped assets)
        return;
    }
    const bool chained = m_preview && job.changes && m_previewGeneration == job.baseGeneration;
    const Handling handling = chained ? handlingOf(*job.changes) : Handling::Rebuild;
    if (handling == Handling::Rebuild) {
        drop(job.generation);
        // Built once edits pause, never for a scene just opened: the path tracer's first frames
        // show it, and a build (seconds) would hold up quitting (shutdown waits for it).
        if (job.changes) m_rebuildTimer->start();
        return;
    }
    QElapsedTimer timer;
    timer.start();
    const relight::EditSummary summary = m_preview->applyCoarse(*job.scene, *job.changes);
    if (handling == Handling::Exact) m_preview->applyFine(); // with any first-answer edits pending
    m_previewGeneration = job.generation;
    const bool first = m_preview->finePending();
    publish(job.generation, QStringLiteral("relight %1: %2, %3 points in %4 ms")
                                .arg(first ? QStringLiteral("first answer") : QStringLiteral("preview"))
                                .arg(kindOf(summary))
                                .arg(summary.pointsTouched)
                                .arg(double(timer.nsecsElapsed()) * 1e-6, 0, 'f', 1));
    if (first) m_fineTimer->start(); // restarted by every drag frame: fires once the drag pauses
    else m_fineTimer->stop();
}

void RelightWorker::refine() {
    // A job waiting to run restarts the timer when it has (a drag goes on).
    if (cancelled() || m_pending || !m_preview || !m_preview->finePending()) return;
    QElapsedTimer timer;
    timer.start();
    const relight::EditSummary summary = m_preview->applyFine();
    publish(m_previewGeneration, QStringLiteral("relight preview after the pause: %1, %2 points in %3 ms")
                                     .arg(kindOf(summary))
                                     .arg(summary.pointsTouched)
                                     .arg(double(timer.nsecsElapsed()) * 1e-6, 0, 'f', 0));
}

void RelightWorker::rebuild() {
    if (cancelled() || !m_latestScene || m_pending) return; // a pending job calls back here
    QElapsedTimer timer;
    timer.start();
    auto created = relight::CoarseToFinePreview::create(*m_latestScene,
                                                        previewSettings(*m_latestScene, m_width, m_height),
                                                        -1, kCoarseStride, /*deferMovedObjects=*/true);
    if (!created) return; // the path tracer shows the scene (and reports real problems)
    m_preview = std::move(created.value());
    m_preview->enableFieldDrags(fieldDragSettings());
    if (m_keptField) m_preview->offerField(*m_keptField);
    m_previewGeneration = m_latestGeneration;
    publish(m_latestGeneration, QStringLiteral("relight preview built in %1 ms (%2 points, %3; coarse-to-fine "
                                               "+%4)")
                                    .arg(double(timer.nsecsElapsed()) * 1e-6, 0, 'f', 0)
                                    .arg(m_preview->fine().points().size())
                                    .arg(kiB(m_preview->fine().stateBytes()))
                                    .arg(kiB(m_preview->extraBytes())));
}

void RelightWorker::publish(quint64 generation, const QString& what) {
    RenderFrame frame;
    frame.kind = RenderFrame::Kind::Relight;
    frame.approximate = m_preview->finePending();
    frame.image = std::make_shared<const util::ImageRGB>(frame.approximate ? m_preview->firstAnswer(m_width, m_height)
                                                                           : m_preview->image(m_width, m_height));
    frame.displayExposureEv = m_shared->exposureEv.load();
    frame.display = toneMap(*frame.image, frame.displayExposureEv);
    frame.generation = generation;
    frame.lastUpdate = what;
    frame.deviceName = QStringLiteral("relight preview (CPU)");
    emit frameReady(std::move(frame));
}

} // namespace wavelit::editor
