// RelightWorker: the instant relighting preview (renderer/relight, docs/relighting.md §6) for the
// viewport, on its own thread beside the render thread (RenderController starts both), so a
// preview build (seconds: every point is ray-cast) never stalls the UI or the path tracer's
// event loop. It owns one CoarseToFinePreview for the current camera (the full preview plus a
// coarse one on every kCoarseStride-th pixel, relight/coarse_to_fine.h) and follows the same jobs
// as the render thread (scene snapshot + change set), newest wins, change sets merge, so each
// step takes every edit that arrived while the previous step ran (one drag frame):
//   environment, light, material colour /      applied to both previews at once (the full
//   emission (cheap, docs/relighting.md §3)    update is tens of ms): an exact frame;
//   object, other material edits (a drag,      applyCoarse, then the corrected first answer
//   a roughness slider)                        (firstAnswer, tens of ms): an APPROXIMATE frame
//                                              (for material edits alone: the full preview's
//                                              untruncated answer, docs/relighting.md §7.0g;
//                                              for an object's translation, once its shadow
//                                              field is built beside the drag: the full
//                                              preview through the field, §7.0k);
//                                              once no job came for kFinePauseMs, applyFine
//                                              (every pending edit merged into one full update)
//                                              and the exact frame;
//   camera, added/removed entities, render     the preview is dropped, rebuilt once no such
//   size                                       edit came for kRebuildQuietMs.
// The first build waits for the first edit (then kRebuildQuietMs of quiet): a scene just opened
// is shown by the path tracer. Frames are RenderFrame::Kind::Relight with `approximate` set for
// a first answer: linear radiance of direct lighting (the preview has no interreflection),
// upsampled (nearest point) to the render size and tone-mapped here.
// The controller decides what the viewport shows (render_controller.h: the hand-over).
// Shutdown cancels a shadow field being built and waits for a running build or edit (not
// interruptible: relight_preview.h; ~0.5-2 s for a 128^2 build on 2 cores, or a full update
// after a drag, docs/relighting.md §7).
#pragma once

#include "viewport/render_frame.h"

#include "relight/coarse_to_fine.h"

#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>

namespace wavelit::editor {

struct RenderShared;

class RelightWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxPreviewPoints = 128; // per side: a 128^2 build is ~2 s on 2 cores (§7)
    static constexpr int kRebuildQuietMs = 400;
    // The coarse preview's pixel stride (docs/relighting.md §6: 4 x fewer coarse points, +3% build
    // time and 7-10% memory over the full preview alone).
    static constexpr int kCoarseStride = 2;
    // "Edits paused": no job for this long after a first answer starts the full update. A 60 Hz
    // mouse sends a move every 16 ms and a first answer takes 15-50 ms (up to ~110 ms under
    // load, docs/relighting.md §7.0c), so during a drag the worker never idles this long; the
    // full update is not interruptible (0.3-2 s CPU), so starting it mid-drag would freeze the
    // preview that long. Longer only delays the exact image after the hand stops.
    static constexpr int kFinePauseMs = 200;

    // The full preview's settings for a render of width x height (what the worker builds; tests
    // compare its frames with RelightPreview::create on the same settings).
    static relight::RelightSettings previewSettings(const scene::Scene& scene, int width, int height);
    // Object translation drags go through the moved object's shadow field once it is built (on a
    // thread of its own from the drag's first frame: CoarseToFinePreview::enableFieldDrags).
    static relight::ShadowFieldSettings fieldDragSettings();

    explicit RelightWorker(std::shared_ptr<RenderShared> shared);
    ~RelightWorker() override;

    // Queued onto the worker's thread. A job without a scene drops the preview.
    void submit(RenderJob job);
    // Queued onto the worker's thread when an object is selected: starts building its shadow
    // field beside the drag that may follow (CoarseToFinePreview::prepareFieldDrag; 0.5-0.9 s of
    // CPU on the bundled scenes, docs/relighting.md §7.0k), if a preview is up to date and no job
    // waits. Its first drag frame then takes the field instead of the coarse first answer.
    void prepareObject(scene::EntityId object);
    // Whether `object`'s drag frames would take its shadow field now (on the worker's thread;
    // tests ask through RenderController::relightFieldReady).
    bool fieldReady(scene::EntityId object);

signals:
    void frameReady(wavelit::editor::RenderFrame frame);
    // The preview does not follow this job (none built yet, dropped): the viewport should show
    // the path tracer's drafts instead.
    void skipped(quint64 generation);

private:
    void step();
    void rebuild();
    void refine(); // kFinePauseMs after a first answer: the exact frame
    void drop(quint64 generation);
    void publish(quint64 generation, const QString& what);
    bool cancelled() const;

    std::shared_ptr<RenderShared> m_shared;
    std::optional<RenderJob> m_pending;
    std::unique_ptr<relight::CoarseToFinePreview> m_preview;
    // The dropped preview's shadow field, offered to the next one (a camera move keeps it valid).
    std::optional<relight::CoarseToFinePreview::KeptField> m_keptField;
    quint64 m_previewGeneration = 0; // the job whose scene the preview holds
    std::shared_ptr<const scene::Scene> m_latestScene; // the newest job's scene (for rebuilds)
    quint64 m_latestGeneration = 0;
    int m_width = 0, m_height = 0; // the render size frames are scaled to
    QTimer* m_rebuildTimer = nullptr;
    QTimer* m_fineTimer = nullptr;
    bool m_stepScheduled = false;
};

} // namespace wavelit::editor
