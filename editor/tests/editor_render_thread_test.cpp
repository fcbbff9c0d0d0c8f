// The render thread at a realistic size (1600x1000, 1.6 MP) on lavapipe, issue 19:
// - the UI thread never stalls more than 50 ms while frames arrive and the exposure changes:
//   tone mapping (~100 ms a frame at 1.6 MP) runs on the render thread, and an exposure change
//   is re-mapped there without restarting the render;
// - destroying the window while a pass runs (a `wavelet` pass at 1.6 MP takes over a minute on
//   lavapipe) returns within 0.5 s, and so does RenderController::shutdown().
// Timings are asserted here because they are the feature; each bound has a wide margin over what
// was measured on a loaded 2-core machine (the figures are printed).
#include "app/editor_options.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "viewport/tone_map.h"
#include "viewport/viewport_widget.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTimer>
#include <QtTest>

#include <memory>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kLoadTimeoutMs = 60000;
constexpr int kRenderTimeoutMs = 240000;
constexpr int kWidth = 1600;
constexpr int kHeight = 1000;
constexpr qint64 kMaxUiStallMs = 50;
constexpr qint64 kMaxQuitMs = 500;

// Nanoseconds this thread has spent runnable but waiting for a CPU (/proc/thread-self/schedstat,
// second field); -1 where the kernel does not say.
qint64 runQueueWaitNs() {
    QFile file("/proc/thread-self/schedstat");
    if (!file.open(QIODevice::ReadOnly)) return -1;
    const QList<QByteArray> fields = file.readAll().split(' ');
    return fields.size() >= 2 ? fields[1].toLongLong() : -1;
}

// Longest gap between the ticks of a 5 ms timer on the UI thread: how long the thread was busy
// or blocked. Time it spent waiting for a CPU that other processes held (ctest -j2 on 2 cores,
// compilers next to it) is not the editor's stall and is taken off each gap when the kernel
// reports it; the raw gap is reported too.
class StallMeter : public QObject {
public:
    StallMeter() {
        connect(&m_timer, &QTimer::timeout, this, [this] {
            const qint64 gapNs = m_sinceTick.nsecsElapsed();
            m_sinceTick.restart();
            const qint64 wait = runQueueWaitNs();
            const qint64 waitedNs = wait >= 0 && m_lastWaitNs >= 0 ? wait - m_lastWaitNs : 0;
            m_lastWaitNs = wait;
            m_maxRawGapMs = std::max(m_maxRawGapMs, gapNs / 1000000);
            m_maxGapMs = std::max(m_maxGapMs, std::max<qint64>(0, gapNs - waitedNs) / 1000000);
            ++m_ticks;
        });
        m_timer.setTimerType(Qt::PreciseTimer);
    }
    void start() {
        m_maxGapMs = m_maxRawGapMs = 0;
        m_ticks = 0;
        m_lastWaitNs = runQueueWaitNs();
        m_sinceTick.start();
        m_timer.start(5);
    }
    void stop() { m_timer.stop(); }
    qint64 maxGapMs() const { return m_maxGapMs; }
    qint64 maxRawGapMs() const { return m_maxRawGapMs; }
    int ticks() const { return m_ticks; }

private:
    QTimer m_timer;
    QElapsedTimer m_sinceTick;
    qint64 m_lastWaitNs = -1;
    qint64 m_maxGapMs = 0;
    qint64 m_maxRawGapMs = 0;
    int m_ticks = 0;
};

RenderSettings largeSettings(render::SamplerKind sampler) {
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.device = render::DeviceChoice::Vulkan;
    settings.sampler = sampler;
    return settings;
}

} // namespace

class EditorRenderThreadTest : public QObject {
    Q_OBJECT
private slots:
    void uiThreadStallsStayShortAt1600x1000();
    void quitDuringPassReturnsWithinHalfSecond();
    void shutdownDuringPassReturnsWithinHalfSecond();

private:
    // Opens the default scene in a new window with the default sampler and waits until a pass
    // is running on the render thread (and has been for a while).
    std::unique_ptr<MainWindow> windowInsidePass();
};

void EditorRenderThreadTest::uiThreadStallsStayShortAt1600x1000() {
    // `bsdf`: its 1.6 MP passes are the shortest (a few seconds on lavapipe), so several frames
    // arrive within the test; tone mapping costs the same whatever the sampler.
    MainWindow window(largeSettings(render::SamplerKind::Bsdf));
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.document()->scene() || window.errors()->count() > 0, kLoadTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    RenderController* renderer = window.renderer();
    ViewportWidget* viewport = window.viewport();
    QTRY_VERIFY_WITH_TIMEOUT(viewport->displayedSamplesPerPixel() >= 1 || window.errors()->count() > 0,
                             kRenderTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    QCOMPARE(viewport->displayedImage().size(), QSize(kWidth, kHeight));

    // What the UI thread used to do per frame (ViewportWidget::showFrame tone-mapped there).
    QElapsedTimer clock;
    clock.start();
    const QImage mapped = toneMap(*renderer->latestFrame().image, 0.5f);
    const qint64 toneMapMs = clock.elapsed();
    QVERIFY(!mapped.isNull());

    StallMeter meter;
    meter.start();
    clock.restart();
    const quint64 generation = renderer->generation();
    const float baseEv = window.document()->scene()->camera.exposureEv;
    int frames = 0;
    int lastSpp = viewport->displayedSamplesPerPixel();
    // Three new frames, each followed by two exposure changes (Display edits through the
    // document, as the toolbar's exposure actions make them).
    for (int round = 0; round < 3; ++round) {
        QTRY_VERIFY_WITH_TIMEOUT(viewport->displayedSamplesPerPixel() > lastSpp || window.errors()->count() > 0,
                                 kRenderTimeoutMs);
        QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
        lastSpp = viewport->displayedSamplesPerPixel();
        ++frames;
        for (int step = 0; step < 2; ++step) {
            const float ev = baseEv + (step == 0 ? 1.0f : -0.5f) * float(round + 1);
            QVERIFY(window.document()->setExposure(ev).ok());
            QCOMPARE(viewport->exposure(), ev);
            QTRY_COMPARE_WITH_TIMEOUT(viewport->displayedExposure(), ev, kRenderTimeoutMs);
            // Re-mapped, not restarted: same render, no samples lost.
            QCOMPARE(renderer->generation(), generation);
            QVERIFY(viewport->displayedSamplesPerPixel() >= lastSpp);
        }
    }
    meter.stop();
    qInfo("%dx%d: %d frames and 6 exposure changes in %.1f s; UI thread's longest stall %lld ms "
          "(%lld ms with waits for a CPU; %d ticks of 5 ms); tone mapping one frame on the UI "
          "thread, as before, took %lld ms",
          kWidth, kHeight, frames, clock.elapsed() / 1000.0, meter.maxGapMs(), meter.maxRawGapMs(),
          meter.ticks(), toneMapMs);
    QVERIFY2(meter.maxGapMs() <= kMaxUiStallMs,
             qPrintable(QString("the UI thread stalled for %1 ms").arg(meter.maxGapMs())));
}

std::unique_ptr<MainWindow> EditorRenderThreadTest::windowInsidePass() {
    // The default sampler (`wavelet`): its 1.6 MP pass takes over a minute on lavapipe.
    auto window = std::make_unique<MainWindow>(largeSettings(RenderSettings{}.sampler));
    window->show();
    window->document()->open(defaultScenePath());
    const auto ready = [&] { return window->renderer()->passRunning() || window->errors()->count() > 0; };
    if (!QTest::qWaitFor(ready, kRenderTimeoutMs)) return nullptr;
    if (window->errors()->count() > 0) {
        qWarning("%s", qPrintable(window->errors()->lastMessage()));
        return nullptr;
    }
    QTest::qWait(500); // well inside the pass, a piece in flight
    if (!window->renderer()->passRunning() || window->renderer()->latestFrame().samplesPerPixel > 0)
        return nullptr; // the first pass cannot have finished yet
    return window;
}

void EditorRenderThreadTest::quitDuringPassReturnsWithinHalfSecond() {
    std::unique_ptr<MainWindow> window = windowInsidePass();
    QVERIFY2(window, "no pass started");
    QElapsedTimer clock;
    clock.start();
    window.reset(); // ~MainWindow -> ~RenderController -> shutdown(): the quit path
    const qint64 ms = clock.elapsed();
    qInfo("destroying the window during a 1600x1000 wavelet pass took %lld ms", ms);
    QVERIFY2(ms <= kMaxQuitMs, qPrintable(QString("quitting took %1 ms").arg(ms)));
}

void EditorRenderThreadTest::shutdownDuringPassReturnsWithinHalfSecond() {
    std::unique_ptr<MainWindow> window = windowInsidePass();
    QVERIFY2(window, "no pass started");
    QElapsedTimer clock;
    clock.start();
    window->renderer()->shutdown(); // what a "Save changes?" quit path calls before closing
    const qint64 ms = clock.elapsed();
    qInfo("RenderController::shutdown() during a 1600x1000 wavelet pass took %lld ms", ms);
    QVERIFY(!window->renderer()->passRunning());
    QVERIFY2(ms <= kMaxQuitMs, qPrintable(QString("shutdown took %1 ms").arg(ms)));
    // The window outlives its stopped renderer: an edit now renders nothing and fails nothing.
    const EntityRef camera{scene::EntityKind::Camera, scene::kInvalidId};
    QVERIFY(window->document()->apply({camera, "fov", 45.0f}).ok());
    QTest::qWait(200);
    QCOMPARE(window->renderer()->latestFrame().samplesPerPixel, 0);
    QCOMPARE(window->errors()->count(), 0);
    clock.restart();
    window.reset();
    QVERIFY2(clock.elapsed() <= kMaxQuitMs, "destroying the window after shutdown was slow");
}

QTEST_MAIN(EditorRenderThreadTest)
#include "editor_render_thread_test.moc"
