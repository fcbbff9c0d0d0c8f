// RenderController: the UI thread's handle on rendering. Starts the render thread and its
// RenderWorker, turns scene snapshots into RenderJobs (render size, device and spp limit from
// RenderSettings) and forwards only frames and errors of the newest job. The UI thread never
// blocks on the render thread, except in the destructor, which cancels and joins (at most one
// pass) so the Vulkan device is destroyed on the thread that created it.
#pragma once

#include "viewport/render_frame.h"

#include "render/render_options.h"

#include <QObject>
#include <QThread>

#include <atomic>
#include <memory>

namespace wavelit::editor {

class RenderWorker;

struct RenderSettings {
    render::DeviceChoice device = render::DeviceChoice::Auto;
    // The product sampler is the editor's default, as the CLI's (architecture.md §5.B).
    render::SamplerKind sampler = render::SamplerKind::Wavelet;
    int width = 0;  // 0: the scene's render defaults
    int height = 0;
    int maxSamplesPerPixel = 0; // 0: progressive forever
    bool validation = false;
};

class RenderController : public QObject {
    Q_OBJECT
public:
    explicit RenderController(RenderSettings settings, QObject* parent = nullptr);
    ~RenderController() override;

    // Restarts rendering with this scene (a new generation). A null scene stops rendering.
    // scenePath: the file its relative asset paths start from.
    void render(std::shared_ptr<const scene::Scene> scene, const QString& scenePath);
    // Stops after the current pass; no more frames are delivered.
    void cancel();

    const RenderSettings& settings() const { return m_settings; }
    const RenderFrame& latestFrame() const { return m_latest; }
    quint64 generation() const { return m_generation; }

signals:
    void frameReady(const wavelit::editor::RenderFrame& frame);
    void failed(const QString& message);

private:
    void onFrame(RenderFrame frame);
    void onFailed(const QString& message, quint64 generation);

    RenderSettings m_settings;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    std::shared_ptr<std::atomic<int>> m_framesInFlight;
    QThread m_thread;
    RenderWorker* m_worker = nullptr; // lives on m_thread, deleted there when it finishes
    RenderFrame m_latest;
    quint64 m_generation = 0;
};

} // namespace wavelit::editor
