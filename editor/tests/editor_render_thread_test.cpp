// The render thread at a realistic size (1600x1000, 1.6 MP) on lavapipe, issue 19:
// - the UI thread never stalls more than 50 ms while frames arrive and the exposure changes:
//   tone mapping (~100 ms a frame at 1.6 MP) runs on the render thread, and an exposure change
//   is re-mapped there without restarting the render;
// - destroying the window while a pass runs (a `wavelet` pass at 1.6 MP takes over a minute on
//   lavapipe) returns within 0.5 s, and so does RenderController::shutdown().
// Timings are asserted here because they are the feature; each bound has a wide margin over what
// was measured on a loaded 2-core machine (the figures are printed; ctest runs this test alone).
// Measured 2026-12-02 (Release, lavapipe, load average 7 on 2 cores): the UI thread's longest
// stall 5-8 ms (longest gap with waits for a CPU 12-148 ms, other processes' load); quitting or
// shutdown() during a wavelet pass 26-52 ms. Before issue 19: tone mapping on the UI thread
// 24-88 ms a frame, quitting during a pass 78 s (the whole pass).
// - destroying the window while the session is still being created (the kernel's compile) also
//   returns within 0.5 s: the render thread is let go to finish on its own.
// 2026-12-05, three busy loops beside the test (load ~3.5): shutdown() during a `wavelet` pass
// took 205-1362 ms (3 of 4 runs over the bound) while the first pass laid out its product cache
// in one uninterruptible step (0.34 s alone, over a second under load); with the layout's centre
// rays traced in bands between interrupt checks, quit 20-68 ms and shutdown() 25-62 ms.
#include "app/editor_options.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "viewport/finishing_threads.h"
#include "viewport/tone_map.h"
#include "viewport/viewport_widget.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTimer>
#include <QtTest>

#include <functional>
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

// This thread's nanoseconds on a CPU and runnable but waiting for one
// (/proc/thread-self/schedstat); -1 where the kernel does not say.
struct SchedTimes {
    qint64 onCpuNs = -1, waitNs = -1;
};
SchedTimes schedTimes() {
    QFile file("/proc/thread-self/schedstat");
    if (!file.open(QIODevice::ReadOnly)) return {};
    const QList<QByteArray> fields = file.readAll().split(' ');
    if (fields.size() < 2) return {};
    return {fields[0].toLongLong(), fields[1].toLongLong()};
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
            const SchedTimes now = schedTimes();
            const bool known = now.waitNs >= 0 && m_last.waitNs >= 0;
            const qint64 waitedNs = known ? now.waitNs - m_last.waitNs : 0;
            const qint64 cpuNs = known ? now.onCpuNs - m_last.onCpuNs : -1;
            m_last = now;
            m_maxRawGapMs = std::max(m_maxRawGapMs, gapNs / 1000000);
            const qint64 gapMs = std::max<qint64>(0, gapNs - waitedNs) / 1000000;
            if (gapMs > m_maxGapMs) {
                m_maxGapMs = gapMs;
                m_maxGapCpuMs = cpuNs / 1000000;
            }
            ++m_ticks;
        });
        m_timer.setTimerType(Qt::PreciseTimer);
    }
    void start() {
        m_maxGapMs = m_maxRawGapMs = m_maxGapCpuMs = 0;
        m_ticks = 0;
        m_last = schedTimes();
        m_sinceTick.start();
        m_timer.start(5);
    }
    void stop() { m_timer.stop(); }
    qint64 maxGapMs() const { return m_maxGapMs; }
    qint64 maxRawGapMs() const { return m_maxRawGapMs; }
    qint64 maxGapCpuMs() const { return m_maxGapCpuMs; } // of it on a CPU (-1: unknown)
    int ticks() const { return m_ticks; }

private:
    QTimer m_timer;
    QElapsedTimer m_sinceTick;
    SchedTimes m_last;
    qint64 m_maxGapMs = 0;
    qint64 m_maxGapCpuMs = 0;
    qint64 m_maxRawGapMs = 0;
    int m_ticks = 0;
};

// Runs the event loop, as the application's does, until `done` holds or timeoutMs passes. (QTRY_*
// and QTest::qWait sleep up to 10 ms between event-processing passes: a stall of the test's own.)
bool spinUntil(const std::function<bool()>& done, int timeoutMs) {
    if (done()) return true;
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done()) loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    poll.start(1);
    loop.exec();
    return done();
}

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
    void quitWhileTheSessionIsCreatedReturnsWithinHalfSecond();

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
        QVERIFY(spinUntil([&] { return viewport->displayedSamplesPerPixel() > lastSpp || window.errors()->count() > 0; },
                          kRenderTimeoutMs));
        QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
        lastSpp = viewport->displayedSamplesPerPixel();
        ++frames;
        // The frame's own display image, made on the render thread: nothing re-mapped here.
        QCOMPARE(viewport->displayedImage().cacheKey(), renderer->latestFrame().display.cacheKey());
        for (int step = 0; step < 2; ++step) {
            const float ev = baseEv + (step == 0 ? 1.0f : -0.5f) * float(round + 1);
            QVERIFY(window.document()->setExposure(ev).ok());
            QCOMPARE(viewport->exposure(), ev);
            QVERIFY(spinUntil([&] { return viewport->displayedExposure() == ev; }, kRenderTimeoutMs));
            QCOMPARE(viewport->displayedImage().cacheKey(), renderer->latestFrame().display.cacheKey());
            // Re-mapped, not restarted: same render, no samples lost.
            QCOMPARE(renderer->generation(), generation);
            QVERIFY(viewport->displayedSamplesPerPixel() >= lastSpp);
        }
    }
    meter.stop();
    qInfo("%dx%d: %d frames and 6 exposure changes in %.1f s; UI thread's longest stall %lld ms "
          "(%lld ms of it on a CPU; longest gap with waits for a CPU %lld ms; %d ticks of 5 ms); "
          "tone mapping one frame on the UI thread, as before, took %lld ms",
          kWidth, kHeight, frames, clock.elapsed() / 1000.0, meter.maxGapMs(), meter.maxGapCpuMs(),
          meter.maxRawGapMs(), meter.ticks(), toneMapMs);
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

// Closing the window right after opening a scene: the render thread is inside the session's
// creation (lavapipe compiles the `wavelet` kernel: 1.6 s alone, 4-7 s with the UI and tests
// beside it), which no interrupt reaches. The window goes within the bound anyway (the thread is
// let go and finishes on its own); that thread ends and is deleted soon after, with no error.
// Before: 4.0-7.1 s on the three bundled scenes.
void EditorRenderThreadTest::quitWhileTheSessionIsCreatedReturnsWithinHalfSecond() {
    auto window = std::make_unique<MainWindow>(largeSettings(RenderSettings{}.sampler));
    window->show();
    window->document()->open(defaultScenePath());
    QTest::qWait(300);
    if (window->renderer()->passRunning() || window->renderer()->latestFrame().image)
        QSKIP("the session was created within 300 ms: nothing left to let go");
    QCOMPARE(window->errors()->count(), 0);
    const int before = finishingThreadCount();
    QElapsedTimer clock;
    clock.start();
    window.reset();
    const qint64 ms = clock.elapsed();
    qInfo("destroying the window 300 ms after opening the scene took %lld ms", ms);
    QVERIFY2(ms <= kMaxQuitMs, qPrintable(QString("quitting took %1 ms").arg(ms)));
    QVERIFY(finishingThreadCount() > before); // the render thread, still compiling, was let go
    QTRY_VERIFY_WITH_TIMEOUT(finishingThreadCount() == 0, kLoadTimeoutMs);
}

QTEST_MAIN(EditorRenderThreadTest)
#include "editor_render_thread_test.moc"
