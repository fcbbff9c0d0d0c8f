// RenderController: the UI thread's handle on rendering. Starts the render thread and its
// RenderWorker, turns scene snapshots into RenderJobs (render size, device and spp limit from
// RenderSettings) and forwards only frames and errors of the newest job. Frames arrive tone-mapped
// (RenderFrame::display, made on the render thread); setExposure re-maps there too. The UI thread
// never blocks on the render thread, except briefly in shutdown() (also run by the destructor),
// which stops the running pass within one piece (~40 ms, gpu_path_tracer.h) and joins; a thread
// inside a step no interrupt reaches is let go to finish on its own (finishing_threads.h). The
// Vulkan device is destroyed on the thread that created it either way (lavapipe and the
// validation layers do not require that, but a device's objects are created and used only there:
// one thread, no locks).
//
// What the viewport shows (displayFrame, docs/relighting.md §6): a second thread runs the
// relighting preview (relight_worker.h) on the same jobs. Of the frames both threads deliver the
// newest generation is shown (a drag's approximate first answer is replaced by the exact
// preview of the same generation once the drag pauses); within one generation the preview stays
// until the path tracer's estimated error (RenderFrame::estimatedRelError, from its own
// samples) drops to kPreviewRelError — the preview's measured relRMSE against converged direct lighting on the
// bundled scenes is 0.12-0.34 (docs/relighting.md §7), so 0.2 is where the tracer's image is as
// good — or the tracer stops (--max-spp). frameReady keeps meaning "a path-traced frame of the
// newest job" (latestFrame, waitForSamples, saveImage).
#pragma once

#include "viewport/render_frame.h"

#include "render/session/render_options.h"
#include "scene/change_set.h"

#include <QElapsedTimer>
#include <QObject>
#include <QThread>

#include <atomic>
#include <memory>

namespace wavelit::editor {

class RelightWorker;
class RenderWorker;
struct RenderShared;

inline constexpr double kPreviewRelError = 0.2;

struct RenderSettings {
    render::DeviceChoice device = render::DeviceChoice::Auto;
    // The product sampler is the editor's default, as the CLI's (architecture.md §5.B).
    render::SamplerKind sampler = render::SamplerKind::Wavelet;
    int width = 0;  // 0: the scene's render defaults
    int height = 0;
    int maxSamplesPerPixel = 0; // 0: progressive forever
    bool validation = false;
    // LightMix (docs/lightmix.md): render light-group layers, and show an edit of a light's
    // intensity, colour or mute or of the environment's intensity by recombining them on the
    // next frame (render/session/light_remix.h) instead of restarting. Costs groups x pixels x
    // 12 bytes of device memory.
    bool lightMix = false;
    // The relighting preview thread (relight_worker.h); off: the path tracer alone.
    bool relightPreview = true;
};

class RenderController : public QObject {
    Q_OBJECT
public:
    explicit RenderController(RenderSettings settings, QObject* parent = nullptr);
    // Runs shutdown().
    ~RenderController() override;

    // Stops rendering for good and joins the render thread: the running pass stops at its next
    // piece boundary (the Vulkan tracer polls every ~40 ms), then the session, its Vulkan device
    // and the worker are destroyed on the render thread. Returns within 0.5 s while a pass is
    // running (measured: editor_render_thread_test). A thread still busy after kJoinMs (a
    // session being created or a scene being swapped in: pipeline compile, sampler-table builds,
    // 2-7 s with `wavelet`; a relighting preview being built) is let go: it finishes that step,
    // sees the cancel and ends on its own (finishing_threads.h). Afterwards render(),
    // setExposure() and setInteractive() do nothing and no frame or error is delivered.
    // Idempotent; for the quit path (e.g. after a "Save changes?" prompt), before the window goes.
    void shutdown();

    // Restarts rendering with this scene (a new generation). A null scene stops rendering.
    // scenePath: the file its relative asset paths start from.
    void render(std::shared_ptr<const scene::Scene> scene, const QString& scenePath);
    // Restarts rendering after an edit: `changes` leads from the scene of the previous render()
    // or renderEdit() to `scene`. The render thread hands it (merged with edits it has not yet
    // started) to the session, which rebuilds and re-uploads only what it invalidates; when its
    // session does not hold the previous scene (a failure, other options) it swaps in the scene.
    void renderEdit(std::shared_ptr<const scene::Scene> scene, const QString& scenePath,
                    const scene::ChangeSet& changes);
    // Stops rendering at the next piece boundary of the running pass (~40 ms); no more frames are
    // delivered. Does not wait: shutdown() also joins.
    void cancel();
    // Display exposure (EV) the render thread tone-maps with; a change re-maps the latest frame
    // there and re-delivers it through frameReady (no restart, accumulation kept).
    void setExposure(float ev);
    float exposure() const { return m_exposureEv; }
    // A viewport drag starts (true) or ends: while it lasts the render thread renders
    // reduced-resolution drafts (render_worker.h); when it ends the full session takes the drag's
    // edits as one update.
    void setInteractive(bool active);
    // The selection changed: a selected object's shadow field is built beside the path tracer,
    // so its first translation drag can take it (RelightWorker::prepareObject).
    void selectionChanged(std::optional<scene::EntityRef> ref);
    // Whether the relighting preview holds `object`'s shadow field ready for a drag (asks the
    // preview's thread and waits for its answer: for tests).
    bool relightFieldReady(scene::EntityId object) const;
    // True while the render thread is inside a pass (tests wait for it).
    bool passRunning() const;

    const RenderSettings& settings() const { return m_settings; }
    const RenderFrame& latestFrame() const { return m_latest; }
    // The newest relighting preview frame of the newest job, shown or not (empty until one came):
    // during a drag the approximate first answers, once it pauses the exact preview.
    const RenderFrame& latestPreview() const { return m_latestPreview; }
    // The frame the viewport shows now (any kind; msSinceEdit set), and whether it is of the
    // newest job (an edit's first frame has arrived).
    const RenderFrame& displayedFrame() const { return m_displayed; }
    int framesDisplayed() const { return m_framesDisplayed; } // displayFrame signals so far
    bool displayedIsCurrent() const { return m_displayed.image && m_displayed.generation == m_generation; }
    quint64 generation() const { return m_generation; }

signals:
    void frameReady(const wavelit::editor::RenderFrame& frame);
    void failed(const QString& message);
    // The frame the viewport should show (see the class comment).
    void displayFrame(const wavelit::editor::RenderFrame& frame);

private:
    void onRelightFrame(RenderFrame frame);
    // The preview follows the edits (its latest word on a job was a frame, not a skip): a draft
    // then never replaces it, so a light drag shows the preview, not the two alternating.
    bool m_relightFollows = false;
    void display(RenderFrame frame);
    std::unique_ptr<QThread> m_relightThread; // null after shutdown()
    RelightWorker* m_relight = nullptr;        // null after shutdown()
    RenderFrame m_displayed;
    RenderFrame m_latestPreview;
    quint64 m_sceneGeneration = 0; // the job that opened the current scene
    int m_framesDisplayed = 0;
    QElapsedTimer m_sinceEdit;

    void submit(RenderJob job);
    void onFrame(RenderFrame frame);
    void onFailed(const QString& message, quint64 generation);

    RenderSettings m_settings;
    std::shared_ptr<RenderShared> m_shared;
    std::unique_ptr<QThread> m_thread; // null after shutdown()
    // Lives on m_thread, deleted there when it finishes; null after shutdown().
    RenderWorker* m_worker = nullptr;
    RenderFrame m_latest;
    quint64 m_generation = 0;
    float m_exposureEv = 0.0f;
};

} // namespace wavelit::editor
