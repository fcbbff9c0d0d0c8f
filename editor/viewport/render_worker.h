// RenderWorker: lives on the render thread and owns the RenderSession (created there, so the
// LLVM pipeline compile of lavapipe never stalls the UI) and its scene copy. Each pass is one
// queued event, so new jobs arriving through the event queue are picked up between passes
// ("newest wins": only the latest pending job is kept). Frames go out through frameReady at most
// every kFrameInterval, plus the first pass after a restart and the last before idling.
//
// Back-pressure: the worker counts frames it has published but the UI has not yet consumed
// (framesInFlight, decremented by RenderController) and skips optional frames while two are
// queued, so a slow UI sees fewer frames instead of a growing queue: double buffering.
#pragma once

#include "viewport/render_frame.h"

#include "render/render_session.h"

#include <QElapsedTimer>
#include <QObject>

#include <atomic>
#include <memory>
#include <optional>

namespace wavelit::editor {

class RenderWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kFrameIntervalMs = 100;
    static constexpr int kMaxFramesInFlight = 2;

    // `cancel` is polled before every pass; `framesInFlight` is shared with the controller.
    RenderWorker(std::shared_ptr<const std::atomic<bool>> cancel,
                 std::shared_ptr<std::atomic<int>> framesInFlight);
    ~RenderWorker() override;

    // Call on the render thread (queued). Replaces any job not yet started.
    void submit(RenderJob job);

signals:
    void frameReady(wavelit::editor::RenderFrame frame);
    void failed(QString message, quint64 generation);

private:
    void scheduleStep();
    void step();
    bool startPendingJob(); // false after reporting an error
    void publish();
    void fail(const QString& message);

    std::shared_ptr<const std::atomic<bool>> m_cancel;
    std::shared_ptr<std::atomic<int>> m_framesInFlight;
    std::optional<RenderJob> m_pending;
    std::unique_ptr<render::RenderSession> m_session;
    render::RenderOptions m_sessionOptions;
    quint64 m_generation = 0;
    int m_maxSpp = 0;
    int m_publishedSpp = -1;
    bool m_stepScheduled = false;
    QElapsedTimer m_sinceFrame;
};

} // namespace wavelit::editor
