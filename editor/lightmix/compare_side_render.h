// CompareSideRender: the render of one side of the LightMix A/B split view (app/lightmix_compare.h)
// that differs from the viewport's render in more than light-group weights — a moved, added or
// removed light, another map, rotation or tint, a material — so it cannot be a remix of the
// viewport's layers and gets its own progressive render instead (docs/lightmix.md "A/B").
//
// A second RenderSession on a copy of the scene with that side's setup, with the viewport's
// options (size, sampler, device, bounces) and no light groups, runs on a thread of its own:
// the session is created, used and destroyed there, so the pipeline compile and the passes never
// stall the UI thread. Frames (the mean radiance so far) come back as queued signals, the first
// pass at once and then at most every kFrameIntervalMs. stop() (and the destructor) cancel the
// render; the running pass stops at its next piece (~40 ms on the Vulkan tracer) and the thread
// ends by itself: stop() does not wait, the destructor does (the editor is closing), for at most
// kJoinMs; a thread still creating its session then is let go (viewport/finishing_threads.h).
#pragma once

#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/image.h"

#include <QObject>
#include <QString>

#include <memory>
#include <string>
#include <vector>

class QThread;

namespace wavelit::editor {

struct CompareSideFrame {
    std::shared_ptr<const util::ImageRGB> image;
    int samplesPerPixel = 0;
    int validationMessages = 0;
};

class CompareSideRender : public QObject {
    Q_OBJECT
public:
    static constexpr int kFrameIntervalMs = 100;

    explicit CompareSideRender(QObject* parent = nullptr);
    ~CompareSideRender() override; // cancels, joins or lets go every render still running

    // Renders `scene` with `options` (lightGroups off) until stop(), or until `maxSpp` samples
    // per pixel when positive. A running render is stopped first. Assets an edit dropped (a new
    // map path) are loaded on the render's thread, relative to `scenePath`.
    void start(std::shared_ptr<const scene::Scene> scene, render::RenderOptions options, int maxSpp,
               const std::string& scenePath);
    void stop();
    bool running() const { return m_scene != nullptr; }
    // The scene being rendered (null when stopped).
    const std::shared_ptr<const scene::Scene>& scene() const { return m_scene; }
    // The latest frame of the running render (no image before its first pass).
    const CompareSideFrame& latest() const { return m_latest; }

signals:
    void frameReady();
    void failed(const QString& message);

private:
    struct Shared;
    std::shared_ptr<Shared> m_shared; // of the running render
    std::shared_ptr<const scene::Scene> m_scene;
    CompareSideFrame m_latest;
    std::vector<QThread*> m_threads; // not yet finished (stopped ones end by themselves)
};

} // namespace wavelit::editor
