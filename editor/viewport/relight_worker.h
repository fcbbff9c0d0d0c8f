// RelightWorker: the instant relighting preview (renderer/relight, docs/relighting.md §6) for the
// viewport, on its own thread beside the render thread (RenderController starts both), so a
// preview build (seconds: every point is ray-cast) never stalls the UI or the path tracer's
// event loop. It owns one RelightPreview for the current camera and follows the same jobs as the
// render thread (scene snapshot + change set), newest wins, change sets merge:
//   environment, light                         applied at once (tens of ms), a frame published;
//   material, object                           applied while their last measured cost (per kind)
//                                              fits kEditBudgetMs, else left for later;
//   camera, added/removed entities, render     the preview is dropped, rebuilt once no such
//   size, an edit left for later               edit came for kRebuildQuietMs;
// The first build waits for the first edit (then kRebuildQuietMs of quiet): a scene just opened
// is shown by the path tracer. Frames are RenderFrame::Kind::Relight: linear radiance of direct lighting (the preview has no
// interreflection), upsampled (nearest point) to the render size and tone-mapped here.
// The controller decides what the viewport shows (render_controller.h: the hand-over).
// Shutdown waits for a running build or edit (not interruptible: relight_preview.h; ~0.5-2 s for
// a 128^2 build on 2 cores, docs/relighting.md §7).
#pragma once

#include "viewport/render_frame.h"

#include "relight/relight_preview.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <map>
#include <memory>
#include <optional>

namespace wavelit::editor {

struct RenderShared;

class RelightWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxPreviewPoints = 128; // per side: a 128^2 build is ~2 s on 2 cores (§7)
    static constexpr double kEditBudgetMs = 100.0;
    static constexpr int kRebuildQuietMs = 400;

    explicit RelightWorker(std::shared_ptr<RenderShared> shared);
    ~RelightWorker() override;

    // Queued onto the worker's thread. A job without a scene drops the preview.
    void submit(RenderJob job);

signals:
    void frameReady(wavelit::editor::RenderFrame frame);
    // The preview does not follow this job (none built yet, dropped, too slow for the edit):
    // the viewport should show the path tracer's drafts instead.
    void skipped(quint64 generation);

private:
    void step();
    void rebuild();
    void publish(quint64 generation, const QString& what);
    bool cancelled() const;

    std::shared_ptr<RenderShared> m_shared;
    std::optional<RenderJob> m_pending;
    std::unique_ptr<relight::RelightPreview> m_preview;
    quint64 m_previewGeneration = 0; // the job whose scene the preview holds
    std::shared_ptr<const scene::Scene> m_latestScene; // the newest job's scene (for rebuilds)
    quint64 m_latestGeneration = 0;
    int m_width = 0, m_height = 0; // the render size frames are scaled to
    std::map<std::string, double> m_lastCostMs; // per EditSummary kind
    QTimer* m_rebuildTimer = nullptr;
    bool m_stepScheduled = false;
};

} // namespace wavelit::editor
