// RenderToFile: File -> Render to file (issue 14). Renders the document's current scene to an
// image file with a budget of samples per pixel or seconds, on a pool thread with its own
// render session (the viewport keeps rendering), and writes it: .exr = linear radiance (float),
// .png = 8-bit sRGB at the given exposure. Progress arrives as signals (queued to the UI thread);
// cancel() stops within one piece of a pass (~40 ms on the Vulkan tracer), and nothing is written.
// The options are the viewport's (size, sampler, device, bounces, seed), so at equal samples the
// file holds the viewport's image.
#pragma once

#include "render/session/render_options.h"
#include "scene/scene.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

namespace wavelit::editor {

// Exactly one of the two is positive.
struct RenderBudget {
    int samplesPerPixel = 0;
    double seconds = 0.0;
};

class RenderToFile : public QObject {
    Q_OBJECT
public:
    explicit RenderToFile(QObject* parent = nullptr);
    ~RenderToFile() override; // cancels and waits for a running render

    // Starts; false (and `error` set) if one is already running or the budget or path is bad.
    bool start(std::shared_ptr<const scene::Scene> scene, const render::RenderOptions& options,
               RenderBudget budget, const QString& path, float exposureEv, QString* error);
    void cancel();
    bool isRunning() const { return m_watcher != nullptr; }

signals:
    // fraction in [0, 1] of the budget, and a line for the progress dialog.
    void progress(double fraction, const QString& text);
    // error empty: written; "cancelled" when cancel() stopped it.
    void finished(const QString& path, const QString& error);

private:
    struct Shared;
    std::shared_ptr<Shared> m_shared;
    QFutureWatcher<QString>* m_watcher = nullptr;
    QString m_path;
};

// "spp" or "seconds" budget check and the message naming what is wrong.
QString checkRenderTarget(const QString& path, const RenderBudget& budget);

} // namespace wavelit::editor
