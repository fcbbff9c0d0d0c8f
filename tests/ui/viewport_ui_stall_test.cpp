// Issue 14: the UI thread never stalls more than 50 ms while the viewport is used: gizmo drags
// of a light (relighting preview edits, path-tracer restarts), environment drags (with the
// default `wavelet` sampler every rotation rebuilds the product tables on the render thread),
// camera orbits (the preview is dropped and rebuilt on its thread), the preview's build, a
// rotate-ring drag of an object and a shape-handle drag of a rect light (with the cross-fades
// from preview to path-traced frame they bring).
// A 5 ms QTimer on the UI thread measures its longest gap; time the thread spent waiting for a
// CPU other processes held (ctest -j2 on 2 cores) is taken off each gap when the kernel reports
// it (/proc/thread-self/schedstat), as in editor_render_thread_test. The bound is the feature;
// the figures are printed.
#include "app/main_window.h"
#include "app/scene_document.h"
#include "app/error_reporter.h"
#include "panels/outline_panel.h"
#include "viewport/render_controller.h"
#include "viewport/light_manipulators.h"
#include "viewport/rotate_gizmo.h"
#include "viewport/scene_picker.h"
#include "viewport/viewport_interaction.h"
#include "viewport/view_projection.h"
#include "viewport/viewport_widget.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTimer>
#include <QtTest>

#include <functional>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr qint64 kMaxUiStallMs = 50;
constexpr int kTimeoutMs = 240000;

qint64 waitedNs() { // this thread's time runnable but waiting for a CPU; -1: unknown
    QFile file("/proc/thread-self/schedstat");
    if (!file.open(QIODevice::ReadOnly)) return -1;
    const QList<QByteArray> fields = file.readAll().split(' ');
    return fields.size() < 2 ? -1 : fields[1].toLongLong();
}

class StallMeter : public QObject {
public:
    StallMeter() {
        m_timer.setTimerType(Qt::PreciseTimer);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            const qint64 gap = m_clock.nsecsElapsed();
            m_clock.restart();
            const qint64 waited = waitedNs();
            const qint64 own = waited >= 0 && m_waited >= 0 ? gap - (waited - m_waited) : gap;
            m_waited = waited;
            m_maxRawMs = std::max(m_maxRawMs, gap / 1000000);
            m_maxMs = std::max(m_maxMs, std::max<qint64>(own, 0) / 1000000);
            ++m_ticks;
        });
    }
    void start() {
        m_waited = waitedNs();
        m_clock.start();
        m_timer.start(5);
    }
    qint64 maxMs() const { return m_maxMs; }
    qint64 maxRawMs() const { return m_maxRawMs; }
    int ticks() const { return m_ticks; }

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_waited = -1, m_maxMs = 0, m_maxRawMs = 0;
    int m_ticks = 0;
};

bool spinUntil(const std::function<bool()>& done, int timeoutMs) {
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] { if (done()) loop.quit(); });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    poll.start(1);
    if (!done()) loop.exec();
    return done();
}

void spinFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// A drag as the mouse makes it: press, `steps` moves 16 ms apart (a 60 Hz mouse), release.
void drag(ViewportWidget* viewport, QPointF fromImage, QPointF toImage, Qt::KeyboardModifiers modifiers,
          int steps = 20) {
    const QPointF from = viewport->imageToWidget(fromImage), to = viewport->imageToWidget(toImage);
    auto send = [&](QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent event(type, at, viewport->mapToGlobal(at), button, buttons, modifiers);
        QCoreApplication::sendEvent(viewport, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= steps; ++i) {
        send(QEvent::MouseMove, from + (to - from) * (double(i) / steps), Qt::NoButton, Qt::LeftButton);
        spinFor(16);
    }
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

} // namespace

class ViewportUiStallTest : public QObject {
    Q_OBJECT
private slots:
    void dragsAndTableRebuildsNeverStallTheUiThread();
};

void ViewportUiStallTest::dragsAndTableRebuildsNeverStallTheUiThread() {
    RenderSettings settings;
    settings.width = 96;
    settings.height = 96;
    settings.device = render::DeviceChoice::Vulkan;
    settings.sampler = render::SamplerKind::Wavelet; // the editor's default: table rebuilds
    MainWindow window(settings);
    window.show();
    StallMeter meter;
    meter.start(); // from the scene's opening on: loading, session creation and the first pass
    QElapsedTimer clock;
    clock.start();
    window.document()->open(QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/ring_on_ground.wlscene"));
    RenderController* renderer = window.renderer();
    ViewportWidget* viewport = window.viewport();
    QVERIFY(spinUntil([&] { return renderer->displayedIsCurrent() || window.errors()->count() > 0; }, kTimeoutMs));
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    auto scene = window.document()->scene();
    const scene::EntityRef softbox{scene::EntityKind::Light, scene->lighting.lights.at(0).id};
    QVERIFY(window.outline()->select(softbox));
    int relightFrames = 0, draftFrames = 0, frames = 0;
    connect(renderer, &RenderController::displayFrame, this, [&](const RenderFrame& f) {
        ++frames;
        relightFrames += f.kind == RenderFrame::Kind::Relight;
        draftFrames += f.kind == RenderFrame::Kind::Draft;
    });
    for (int round = 0; round < 2; ++round) {
        // The light by its gizmo, the environment by Ctrl + drag, the camera by a plain drag.
        const QSize size = viewport->imageSize();
        const auto handle = ViewProjection(window.document()->scene()->camera, size.width(), size.height())
                                .project(*handlePosition(*window.document()->scene(), softbox));
        QVERIFY(handle);
        const QPointF at(handle->x, handle->y);
        drag(viewport, at, at + QPointF(round % 2 ? -8 : 8, 4), Qt::NoModifier);
        spinFor(600); // the preview is built once edits pause
        drag(viewport, QPointF(20, 80), QPointF(40, 80), Qt::ControlModifier);
        QVERIFY(spinUntil([&] { return renderer->displayedIsCurrent(); }, kTimeoutMs));
        spinFor(600);
        if (round == 1) drag(viewport, QPointF(48, 20), QPointF(60, 24), Qt::NoModifier, 10);
        QVERIFY(spinUntil([&] { return renderer->displayedIsCurrent(); }, kTimeoutMs));
        QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    }
    // The rotate gizmo and a shape handle (with the preview -> path-traced cross-fades between):
    // the ring object turned by its first ring, the softbox (brought into view) widened.
    const qint64 beforeGizmoMs = meter.maxMs();
    const scene::EntityRef ring{scene::EntityKind::Object, window.document()->scene()->objects.at(0).id};
    QVERIFY(window.document()->apply({softbox, "position", glm::vec3(0.8f, 1.2f, 0.8f)}));
    QVERIFY(spinUntil([&] { return renderer->displayedIsCurrent(); }, kTimeoutMs));
    window.interaction()->setGizmoMode(GizmoMode::Rotate);
    QVERIFY(window.outline()->select(ring));
    const QSize size = viewport->imageSize();
    const float pxScale = viewport->imagePixelsPerScreenPixel();
    const auto rings = rotateGeometry(*window.document()->scene(), ring,
                                      ViewProjection(window.document()->scene()->camera, size.width(), size.height()), pxScale);
    QVERIFY(rings && !rings->rings.empty());
    const RotateRing& r0 = rings->rings.front();
    const glm::vec2 p = r0.points[r0.grabIndex], t = r0.tangents[r0.grabIndex] * (0.4f * rings->ringRadiusImagePx);
    drag(viewport, QPointF(p.x, p.y), QPointF(p.x + t.x, p.y + t.y), Qt::NoModifier);
    QVERIFY(spinUntil([&] { return renderer->displayedIsCurrent(); }, kTimeoutMs));
    spinFor(400);
    QVERIFY(window.outline()->select(softbox));
    const auto shape = manipulatorGeometry(*window.document()->scene(), softbox,
                                           ViewProjection(window.document()->scene()->camera, size.width(), size.height()), pxScale);
    QVERIFY(shape && !shape->handles.empty());
    const qint64 afterRotateMs = meter.maxMs();
    const glm::vec2 h = shape->handles.front().pixel;
    drag(viewport, QPointF(h.x, h.y), QPointF(h.x + 4, h.y), Qt::NoModifier);
    QVERIFY(spinUntil([&] { return renderer->displayedIsCurrent(); }, kTimeoutMs));
    spinFor(400);
    window.interaction()->setGizmoMode(GizmoMode::Move);
    qInfo("longest stall before the rotate and shape-handle drags %lld ms, after the rotate drag %lld ms, after "
          "the shape-handle drag %lld ms", beforeGizmoMs, afterRotateMs, meter.maxMs());
    QVERIFY(spinUntil([&] { return renderer->latestFrame().samplesPerPixel >= 1; }, kTimeoutMs));
    qInfo("96x96 wavelet: %d frames shown (%d relight previews, %d drafts) in %.1f s; UI thread's longest "
          "stall %lld ms (longest gap with waits for a CPU %lld ms; %d ticks of 5 ms)",
          frames, relightFrames, draftFrames, clock.elapsed() / 1000.0, meter.maxMs(), meter.maxRawMs(),
          meter.ticks());
    QVERIFY2(meter.maxMs() <= kMaxUiStallMs, qPrintable(QString("the UI thread stalled for %1 ms").arg(meter.maxMs())));
}

QTEST_MAIN(ViewportUiStallTest)
#include "viewport_ui_stall_test.moc"
