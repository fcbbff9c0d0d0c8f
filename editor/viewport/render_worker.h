// RenderWorker: lives on the render thread and owns the RenderSession (created there, so the
// LLVM pipeline compile of lavapipe never stalls the UI) and its scene copy. Each pass is one
// queued event, so new jobs arriving through the event queue are picked up between passes
// ("newest wins": only the latest pending job is kept). Frames go out through frameReady at most
// every kFrameInterval, plus the first pass after a restart and the last before idling.
//
// Passes are interruptible: the session polls RenderShared between the ~40 ms pieces of a pass
// (gpu_path_tracer.h) and stops the pass early when the controller is shutting down or has queued
// a request (a new job, an exposure change); the worker returns to its event loop, handles the
// request and resumes the same pass (nothing is lost). So a request waits at most one piece,
// never a whole pass (up to half a minute at 1.6 MP with `wavelet` on lavapipe).
//
// Edits: a job carrying a change set (RenderController::renderEdit) is applied to the session
// (RenderSession::applyChanges: only what it invalidates is rebuilt and uploaded) when the session
// holds the scene the change set starts from; a newer edit replacing one not yet started merges
// into it. Otherwise the whole scene is swapped in (setScene).
//
// LightMix (RenderSettings::lightMix, docs/lightmix.md): the session renders light-group layers of
// remixBaseScene (every light unmuted) and each frame is their weighted sum. A job whose scene
// differs from the rendered one only in light intensity, colour, mute or the environment's
// intensity (remixWeights) keeps the session and its samples: the weights change and the frame is
// re-published at once; any other edit swaps in the new scene.
//
// Drafts (issue 14): a second, reduced-resolution session (1/kDraftDivisor per side, BSDF
// sampling: no sampler tables to rebuild) renders while a viewport drag lasts
// (RenderShared::interactive) and once after each edit before the full session's first frame,
// so an edit's first frame costs a 1/16-size pass instead of a table rebuild and a full pass.
// Its frames (RenderFrame::Kind::Draft) are enlarged to the render size by whole pixels. Each
// session takes the jobs it has not seen as one merged update when it renders next
// (session_slot.h): during a drag the full session does nothing, and when the drag ends it
// applies the drag's edits at once.
//
// Display: the worker tone-maps each published frame (tone_map.h) with RenderShared::exposureEv
// into RenderFrame::display, so the UI thread only paints. retoneMap() re-publishes the latest
// frame's samples with the current exposure (a Display edit: no restart, no lost samples).
//
// Back-pressure: the worker counts frames it has published but the UI has not yet consumed
// (framesInFlight, decremented by RenderController) and skips optional frames while two are
// queued, so a slow UI sees fewer frames instead of a growing queue: double buffering.
#pragma once

#include "viewport/render_frame.h"

#include "viewport/session_slot.h"

#include "render/session/render_session.h"

#include <QElapsedTimer>
#include <QObject>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

namespace wavelit::editor {

// State the UI thread (RenderController) and the render thread (RenderWorker) share; atomics
// only, no locks.
struct RenderShared {
    std::atomic<bool> cancel{false};         // set once by shutdown: stop within one piece
    std::atomic<int> framesInFlight{0};      // published, not yet taken by the controller
    std::atomic<int> pendingRequests{0};     // queued submit/retoneMap calls not yet handled
    std::atomic<float> exposureEv{0.0f};     // display exposure for tone mapping
    std::atomic<bool> retoneMapQueued{false}; // a retoneMap call is queued (coalesces changes)
    std::atomic<bool> passRunning{false};    // inside RenderSession::renderPass
    std::atomic<bool> interactive{false};    // a viewport drag lasts: render drafts
};

class RenderWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kFrameIntervalMs = 100;
    static constexpr int kMaxFramesInFlight = 2;
    static constexpr int kDraftDivisor = 4; // render pixels per draft pixel, per side
    static constexpr int kDraftMaxSpp = 64; // a drag held still this long refines at full size

    explicit RenderWorker(std::shared_ptr<RenderShared> shared);
    ~RenderWorker() override;

    // Call on the render thread (queued), after RenderShared::pendingRequests was incremented
    // for the call. Replaces any job not yet started.
    void submit(RenderJob job);
    // Same contract: re-tone-maps the latest published frame with RenderShared::exposureEv and
    // publishes it again (if there is one).
    void retoneMap();
    // Same contract: a drag ended (RenderShared::interactive is false): render at full size.
    void wake();

signals:
    void frameReady(wavelit::editor::RenderFrame frame);
    void failed(QString message, quint64 generation);

private:
    void scheduleStep();
    void step();
    bool startPendingJob(); // false after reporting an error
    bool wantDraft() const;
    bool wantsDraftSession() const; // drafts on and the job's options allow them
    void draftStep();
    void publishDraft();
    static render::RenderOptions draftOptions(const render::RenderOptions& full);
    // LightMix: shows `job` by new weights over the session's layers; false when it cannot.
    bool tryRemix(const RenderJob& job);
    util::Result<util::ImageRGB> sessionImage(); // the beauty, or the LightMix weighted sum
    void publish();
    void emitFrame(RenderFrame frame);
    void fail(const QString& message);
    bool interrupted() const;

    std::shared_ptr<RenderShared> m_shared;
    std::optional<RenderJob> m_pending;
    RenderJob m_job; // the current job (its scene with assets loaded)
    SessionSlot m_full;  // the path tracer at the render size
    SessionSlot m_draft; // the reduced-resolution draft
    bool m_draftsEnabled = true;
    bool m_draftShown = false; // the draft published a frame of the current job
    int m_draftSpp = 0;
    quint64 m_generation = 0;
    int m_maxSpp = 0;
    int m_publishedSpp = -1;
    bool m_stepScheduled = false;
    QElapsedTimer m_sinceFrame;
    RenderFrame m_lastFrame; // the latest published frame of m_generation (for retoneMap)
    // LightMix: the scene the session renders, the weights of the shown scene's groups, and
    // whether the current generation is a remix (the status label says so).
    std::shared_ptr<const scene::Scene> m_renderedScene;
    std::vector<glm::vec3> m_weights;
    bool m_remixed = false;
    QElapsedTimer m_remixTimer; // valid while tryRemix publishes (the frame says its cost)
    std::shared_ptr<const std::vector<util::ImageRGB>> m_lastLayers; // sessionImage's, for the frame
};

} // namespace wavelit::editor
