#include "lightmix/compare_side_render.h"

#include "viewport/finishing_threads.h"

#include "render/session/render_session.h"
#include "scene/scene_io.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <memory>

namespace wavelit::editor {
namespace {

// An edit's new mesh or map path leaves the asset unloaded until a render thread loads it.
bool missingAssets(const scene::Scene& scene) {
    for (const auto& object : scene.objects)
        if (!object.mesh) return true;
    return !scene.lighting.environment.path.empty() && !scene.lighting.environment.image;
}

} // namespace

struct CompareSideRender::Shared {
    std::atomic<bool> cancel{false};
};

CompareSideRender::CompareSideRender(QObject* parent) : QObject(parent) {}

CompareSideRender::~CompareSideRender() {
    stop();
    // Each ends within one piece of a pass; one still creating its session is let go.
    const QDeadlineTimer deadline(kJoinMs);
    for (QThread* thread : m_threads) {
        disconnect(thread, nullptr, this, nullptr); // its finished handler would delete it
        joinOrLetFinish(std::unique_ptr<QThread>(thread), deadline);
    }
}

void CompareSideRender::stop() {
    if (m_shared) m_shared->cancel.store(true);
    m_shared.reset();
    m_scene.reset();
    m_latest = {};
}

void CompareSideRender::start(std::shared_ptr<const scene::Scene> scene, render::RenderOptions options,
                              int maxSpp, const std::string& scenePath) {
    stop();
    options.lightGroups = false;
    auto shared = std::make_shared<Shared>();
    m_shared = shared;
    m_scene = scene;
    QPointer<CompareSideRender> self(this);
    // Runs on the render's own thread; reports reach the UI thread queued, and only while this
    // render is still the current one (a restart or stop() makes its frames stale).
    auto deliver = [self, shared](CompareSideFrame frame) {
        QMetaObject::invokeMethod(self.data(), [self, shared, frame = std::move(frame)] {
            if (!self || self->m_shared != shared) return;
            self->m_latest = frame;
            emit self->frameReady();
        }, Qt::QueuedConnection);
    };
    auto report = [self, shared](QString message) {
        QMetaObject::invokeMethod(self.data(), [self, shared, message] {
            if (!self || self->m_shared != shared) return;
            emit self->failed(message);
        }, Qt::QueuedConnection);
    };
    QThread* thread = QThread::create([scene, options, maxSpp, scenePath, shared, deliver, report] {
        std::shared_ptr<const scene::Scene> complete = scene;
        if (missingAssets(*scene)) {
            auto loaded = std::make_shared<scene::Scene>(*scene);
            if (auto status = scene::loadAssets(*loaded, scenePath); !status)
                return report(QString::fromStdString(status.error().message()));
            complete = std::move(loaded);
        }
        auto created = render::RenderSession::create(*complete, options);
        if (!created) return report(QString::fromStdString(created.error().message()));
        std::unique_ptr<render::RenderSession> session = std::move(created.value());
        session->setInterruptCheck([shared] { return shared->cancel.load(); });
        QElapsedTimer sinceFrame;
        while (!shared->cancel.load()) {
            if (maxSpp > 0 && session->samplesPerPixel() >= maxSpp) { // done: idle until stopped
                QThread::msleep(20);
                continue;
            }
            const int before = session->samplesPerPixel();
            if (auto status = session->renderPass(); !status)
                return report(QString::fromStdString(status.error().message()));
            const int spp = session->samplesPerPixel();
            if (spp == before) continue; // interrupted: cancelled
            const bool last = maxSpp > 0 && spp >= maxSpp;
            if (sinceFrame.isValid() && sinceFrame.elapsed() < kFrameIntervalMs && !last) continue;
            auto image = session->image();
            if (!image) return report(QString::fromStdString(image.error().message()));
            sinceFrame.start();
            deliver({std::make_shared<const util::ImageRGB>(std::move(image.value())), spp,
                     session->stats().validationMessages});
        }
    });
    thread->setObjectName("wavelit-compare-render");
    connect(thread, &QThread::finished, this, [this, thread] {
        m_threads.erase(std::remove(m_threads.begin(), m_threads.end(), thread), m_threads.end());
        thread->deleteLater();
    });
    m_threads.push_back(thread);
    thread->start();
}

} // namespace wavelit::editor
