#include "viewport/relight_worker.h"

#include "viewport/render_worker.h"
#include "viewport/tone_map.h"

#include "relight/sphere_level.h"

#include <algorithm>

namespace wavelit::editor {
namespace {

enum class Handling { Apply, Budgeted, Rebuild };

// What the preview does with an edit (relight_preview.h: what each edit rebuilds).
Handling handlingOf(const scene::ChangeSet& changes) {
    if (changes.changeKind() == scene::ChangeKind::Rebuild) return Handling::Rebuild;
    Handling handling = Handling::Apply;
    for (const scene::Invalidation& inv : changes.invalidations()) {
        switch (inv.factor) {
        case scene::FactorKind::Camera: return Handling::Rebuild;
        case scene::FactorKind::ObjectGeometry:
        case scene::FactorKind::ObjectMaterial:
        case scene::FactorKind::MaterialBrdf: handling = Handling::Budgeted; break;
        default: break;
        }
    }
    for (const scene::Edit& edit : changes.edits())
        if (const auto* p = std::get_if<scene::PropertyEdit>(&edit))
            if (p->entity.kind == scene::EntityKind::Render) return Handling::Rebuild;
    return handling;
}

// The EditSummary kind an edit of this handling will report, for the per-kind budget.
std::string budgetKind(const scene::ChangeSet& changes) {
    for (const scene::Invalidation& inv : changes.invalidations())
        if (inv.factor == scene::FactorKind::ObjectGeometry) return "object";
    return "material";
}

bool assetsLoaded(const scene::Scene& scene) {
    for (const auto& object : scene.objects)
        if (!object.mesh) return false;
    return scene.lighting.environment.path.empty() || scene.lighting.environment.image;
}

} // namespace

RelightWorker::RelightWorker(std::shared_ptr<RenderShared> shared) : m_shared(std::move(shared)) {
    m_rebuildTimer = new QTimer(this);
    m_rebuildTimer->setSingleShot(true);
    m_rebuildTimer->setInterval(kRebuildQuietMs);
    connect(m_rebuildTimer, &QTimer::timeout, this, &RelightWorker::rebuild);
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

void RelightWorker::step() {
    if (cancelled() || !m_pending) return;
    RenderJob job = std::move(*m_pending);
    m_pending.reset();
    m_latestScene = job.scene;
    m_latestGeneration = job.generation;
    m_width = job.options.width;
    m_height = job.options.height;
    if (!job.scene || !assetsLoaded(*job.scene) || job.options.width <= 0 || job.options.height <= 0) {
        m_preview.reset(); // nothing to preview (the render thread loads dropped assets)
        m_previewGeneration = 0;
        emit skipped(job.generation);
        return;
    }
    const bool chained = m_preview && job.changes && m_previewGeneration == job.baseGeneration;
    if (!chained) { // a newly opened scene, or an edit after the preview was dropped
        m_preview.reset();
        m_previewGeneration = 0;
        // Built once edits pause, never for a scene just opened: the path tracer's first frames
        // show it, and a build (seconds) would hold up quitting (shutdown waits for it).
        if (job.changes) m_rebuildTimer->start();
        emit skipped(job.generation);
        return;
    }
    const Handling handling = handlingOf(*job.changes);
    if (handling == Handling::Budgeted) {
        const auto cost = m_lastCostMs.find(budgetKind(*job.changes));
        if (cost != m_lastCostMs.end() && cost->second > kEditBudgetMs) {
            m_preview.reset(); // too slow to follow a drag: rebuilt when it ends
            m_previewGeneration = 0;
            m_rebuildTimer->start();
            emit skipped(job.generation);
            return;
        }
    }
    if (handling == Handling::Rebuild) {
        m_preview.reset();
        m_previewGeneration = 0;
        m_rebuildTimer->start();
        emit skipped(job.generation);
        return;
    }
    QElapsedTimer timer;
    timer.start();
    const relight::EditSummary summary = m_preview->applyChanges(*job.scene, *job.changes);
    const double ms = double(timer.nsecsElapsed()) * 1e-6;
    m_lastCostMs[summary.kind] = ms;
    m_previewGeneration = job.generation;
    publish(job.generation, QStringLiteral("relight preview: %1, %2 points in %3 ms")
                                .arg(QString::fromStdString(summary.kind))
                                .arg(summary.pointsTouched)
                                .arg(ms, 0, 'f', 1));
}

void RelightWorker::rebuild() {
    if (cancelled() || !m_latestScene || m_pending) return; // a pending job calls back here
    relight::RelightSettings settings;
    // One point per render pixel up to kMaxPreviewPoints per side, the aspect kept.
    const double shrink = std::min(1.0, double(kMaxPreviewPoints) / double(std::max(m_width, m_height)));
    settings.width = std::max(1, int(double(m_width) * shrink + 0.5));
    settings.height = std::max(1, int(double(m_height) * shrink + 0.5));
    settings.level = relight::chooseSphereLevel(*m_latestScene).level;
    QElapsedTimer timer;
    timer.start();
    auto created = relight::RelightPreview::create(*m_latestScene, settings);
    if (!created) return; // the path tracer shows the scene (and reports real problems)
    m_preview = std::move(created.value());
    m_previewGeneration = m_latestGeneration;
    publish(m_latestGeneration, QStringLiteral("relight preview built in %1 ms")
                                    .arg(double(timer.nsecsElapsed()) * 1e-6, 0, 'f', 0));
}

void RelightWorker::publish(quint64 generation, const QString& what) {
    RenderFrame frame;
    frame.kind = RenderFrame::Kind::Relight;
    frame.image = std::make_shared<const util::ImageRGB>(m_preview->image(m_width, m_height));
    frame.displayExposureEv = m_shared->exposureEv.load();
    frame.display = toneMap(*frame.image, frame.displayExposureEv);
    frame.generation = generation;
    frame.lastUpdate = what;
    frame.deviceName = QStringLiteral("relight preview (CPU)");
    emit frameReady(std::move(frame));
}

} // namespace wavelit::editor
