// Issue 13 in the editor: an object drag shows the coarse-to-fine relighting preview's corrected
// first answer on every drag frame (labelled approximate in the frame and the status label), then,
// as the drag goes on, the full preview through the object's shadow field (built beside the drag),
// and once the drag pauses the exact preview, which equals a preview built from scratch on the
// final scene; selecting the object builds its field before a drag, whose first frame then takes
// it (relight_worker.h; docs/relighting.md §6, §7.0k). Real window, real mouse events through the
// move gizmo, the path tracer on lavapipe with validation on; no timing is asserted.
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/outline_panel.h"
#include "panels/render_status_label.h"
#include "viewport/move_gizmo.h"
#include "viewport/relight_worker.h"
#include "viewport/render_controller.h"
#include "viewport/view_projection.h"
#include "viewport/viewport_widget.h"

#include "relight/relight_preview.h"
#include "util/image_compare.h"

#include <QTreeWidget>
#include <QtTest>

#include <cmath>
#include <optional>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kTimeoutMs = 240000;
constexpr int kSize = 64;
constexpr int kDragFrames = 4;
// Drag frames, kFieldFrameGapMs apart (under kFinePauseMs: the drag does not pause), until the
// shadow field is in: its build takes ~0.5 s alone, a few seconds beside the tracer.
constexpr int kMaxFieldFrames = 400;
constexpr int kFieldFrameGapMs = 40;

void sendMouse(ViewportWidget* viewport, QEvent::Type type, QPointF imagePoint, Qt::MouseButton button,
               Qt::MouseButtons buttons) {
    const QPointF at = viewport->imageToWidget(imagePoint);
    QMouseEvent event(type, at, viewport->mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &event);
}

} // namespace

class ViewportRelightDragTest : public QObject {
    Q_OBJECT
private slots:
    void objectDragShowsFirstAnswersThenTheExactPreview();
};

void ViewportRelightDragTest::objectDragShowsFirstAnswersThenTheExactPreview() {
    RenderSettings settings;
    settings.width = kSize;
    settings.height = kSize;
    settings.device = render::DeviceChoice::Vulkan;
    settings.sampler = render::SamplerKind::Mis;
    settings.validation = true;
    MainWindow window(settings);
    window.show();
    window.document()->open(QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/ring_on_ground.wlscene"));
    RenderController* renderer = window.renderer();
    ViewportWidget* viewport = window.viewport();
    QTRY_VERIFY_WITH_TIMEOUT(renderer->displayedIsCurrent() || window.errors()->count() > 0, kTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));

    // The preview is built after the first edit, once edits pause (relight_worker.h).
    const scene::EntityRef ring{scene::EntityKind::Object, window.document()->scene()->objects.at(0).id};
    const glm::vec3 start = window.document()->scene()->objects.at(0).transform.translation;
    QVERIFY(window.document()->apply({ring, "translation", start + glm::vec3(0.02f, 0.0f, 0.0f)}));
    QTRY_VERIFY_WITH_TIMEOUT(renderer->latestPreview().image && !renderer->latestPreview().approximate,
                             kTimeoutMs);
    qInfo("built: %s", qPrintable(renderer->latestPreview().lastUpdate));

    // The drag: press on the ring's move gizmo (its centre square), kDragFrames moves; after each,
    // the frame on screen is that edit's preview, an approximate first answer.
    QVERIFY(window.outline()->select(ring));
    QTRY_VERIFY(!viewport->imageSize().isEmpty());
    const QSize size = viewport->imageSize();
    // Where the ring's move gizmo is now (its centre square), in image pixels.
    auto gizmoCentre = [&]() -> std::optional<QPointF> {
        const auto gizmo = gizmoGeometry(*window.document()->scene(), ring,
                                         ViewProjection(window.document()->scene()->camera, size.width(), size.height()),
                                         viewport->imagePixelsPerScreenPixel());
        if (!gizmo) return std::nullopt;
        return QPointF(gizmo->centre.x, gizmo->centre.y);
    };
    const auto gizmo = gizmoCentre();
    QVERIFY(gizmo);
    const QPointF from = *gizmo;
    sendMouse(viewport, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= kDragFrames; ++i) {
        const quint64 before = renderer->generation();
        sendMouse(viewport, QEvent::MouseMove, from + QPointF(1.5 * i, 0.5 * i), Qt::NoButton, Qt::LeftButton);
        QVERIFY2(renderer->generation() > before, "the move made no edit");
        const quint64 generation = renderer->generation();
        const bool arrived = QTest::qWaitFor(
            [&] {
                return renderer->displayedFrame().generation == generation &&
                       renderer->displayedFrame().kind == RenderFrame::Kind::Relight;
            },
            kTimeoutMs);
        const RenderFrame& shown = renderer->displayedFrame();
        QVERIFY2(arrived, qPrintable(QString("drag frame %1 (generation %2): shown is kind %3 of generation %4 (%5); "
                                             "the newest preview is of generation %6 (%7)")
                                         .arg(i).arg(generation).arg(int(shown.kind)).arg(shown.generation)
                                         .arg(shown.lastUpdate).arg(renderer->latestPreview().generation)
                                         .arg(renderer->latestPreview().lastUpdate)));
        qInfo("drag frame %d: %s (%.0f ms after the edit)", i, qPrintable(shown.lastUpdate), shown.msSinceEdit);
        QVERIFY2(shown.approximate, qPrintable(shown.lastUpdate));
        QVERIFY(shown.image && shown.image->width == kSize && shown.image->height == kSize);
        QVERIFY2(window.statusLabel()->text().contains("approximate first answer"),
                 qPrintable(window.statusLabel()->text()));
    }
    // The drag goes on (back and forth): the ring's shadow field, built beside the drag since its
    // first frame, takes over — the full preview through the field, still approximate.
    bool fieldFrame = false;
    int moves = kDragFrames;
    for (; moves < kDragFrames + kMaxFieldFrames && !fieldFrame; ++moves) {
        const int i = moves + 1;
        sendMouse(viewport, QEvent::MouseMove, from + QPointF(1.5 * (kDragFrames - i % 3), 0.5 * kDragFrames),
                  Qt::NoButton, Qt::LeftButton);
        const quint64 generation = renderer->generation();
        QTRY_VERIFY_WITH_TIMEOUT(renderer->latestPreview().generation == generation, kTimeoutMs);
        QVERIFY2(renderer->latestPreview().approximate, qPrintable(renderer->latestPreview().lastUpdate));
        fieldFrame = renderer->latestPreview().lastUpdate.contains("shadowField");
        QTest::qWait(kFieldFrameGapMs);
    }
    qInfo("first shadow-field frame after %d drag frames: %s", moves, qPrintable(renderer->latestPreview().lastUpdate));
    QVERIFY2(fieldFrame, qPrintable(renderer->latestPreview().lastUpdate));
    sendMouse(viewport, QEvent::MouseButtonRelease, from + QPointF(1.5 * kDragFrames, 0.5 * kDragFrames),
              Qt::LeftButton, Qt::NoButton);
    const quint64 last = renderer->generation();
    const glm::vec3 moved = window.document()->scene()->objects.at(0).transform.translation;
    QVERIFY2(glm::length(moved - start) > 0.03f, "the drag did not move the ring");

    // The pause: the exact preview of the last drag frame, equal to one built from scratch.
    QTRY_VERIFY_WITH_TIMEOUT(renderer->latestPreview().generation == last && renderer->latestPreview().image &&
                                 !renderer->latestPreview().approximate,
                             kTimeoutMs);
    QCOMPARE(renderer->generation(), last);
    qInfo("after the pause: %s", qPrintable(renderer->latestPreview().lastUpdate));
    QVERIFY2(renderer->latestPreview().lastUpdate.contains("shadowField settled"),
             qPrintable(renderer->latestPreview().lastUpdate));
    const scene::Scene& finalScene = *window.document()->scene();
    auto scratch = relight::RelightPreview::create(finalScene, RelightWorker::previewSettings(finalScene, kSize, kSize));
    QVERIFY(scratch);
    const double diff = util::maxRelativeDifference(*renderer->latestPreview().image, (*scratch)->image(kSize, kSize));
    qInfo("exact preview vs from scratch: max relative difference %.3g", diff);
    QVERIFY(diff <= 1e-6);
    // On screen: the exact preview, or the path tracer that took over from it — never the first answer.
    QVERIFY(!renderer->displayedFrame().approximate);
    if (renderer->displayedFrame().kind == RenderFrame::Kind::Relight)
        QVERIFY2(window.statusLabel()->text().contains("exact preview"), qPrintable(window.statusLabel()->text()));

    // The path tracer follows the drag's edits with no validation message.
    QTRY_VERIFY_WITH_TIMEOUT((renderer->latestFrame().generation == last && renderer->latestFrame().samplesPerPixel >= 1) ||
                                 window.errors()->count() > 0,
                             kTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    QCOMPARE(renderer->latestFrame().validationMessages, 0);

    // A roughness edit (the property panel's path: no drag) takes the same route: a first answer
    // (reported, not asserted: the tracer may hand over first), then the exact preview.
    int approximateShown = 0;
    const auto counter = connect(renderer, &RenderController::displayFrame, this, [&](const RenderFrame& f) {
        approximateShown += f.kind == RenderFrame::Kind::Relight && f.approximate;
    });
    const scene::EntityRef gold{scene::EntityKind::Material, window.document()->scene()->materials.at(0).id};
    QVERIFY(window.document()->apply({gold, "roughness", 0.35f}));
    const quint64 roughnessEdit = renderer->generation();
    QTRY_VERIFY_WITH_TIMEOUT(renderer->latestPreview().generation == roughnessEdit && renderer->latestPreview().image &&
                                 !renderer->latestPreview().approximate,
                             kTimeoutMs);
    disconnect(counter);
    qInfo("roughness edit: %d approximate frame(s) shown; %s", approximateShown,
          qPrintable(renderer->latestPreview().lastUpdate));
    const scene::Scene& rougher = *window.document()->scene();
    auto scratch2 = relight::RelightPreview::create(rougher, RelightWorker::previewSettings(rougher, kSize, kSize));
    QVERIFY(scratch2);
    const double diff2 = util::maxRelativeDifference(*renderer->latestPreview().image, (*scratch2)->image(kSize, kSize));
    qInfo("exact preview after the roughness edit vs from scratch: max relative difference %.3g", diff2);
    QVERIFY(diff2 <= 1e-6);
    QTRY_VERIFY_WITH_TIMEOUT((renderer->latestFrame().generation == roughnessEdit &&
                              renderer->latestFrame().samplesPerPixel >= 1) ||
                                 window.errors()->count() > 0,
                             kTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    QCOMPARE(renderer->latestFrame().validationMessages, 0);

    // Selecting the ring builds its field beside the tracer (the caches; the field itself stayed
    // from the drag), so the next drag's first frame already goes through it.
    window.outline()->tree()->clearSelection();
    QVERIFY(window.outline()->select(ring));
    QTRY_VERIFY_WITH_TIMEOUT(renderer->relightFieldReady(ring.id), kTimeoutMs);
    const auto gizmo2 = gizmoCentre();
    QVERIFY(gizmo2);
    const QPointF from2 = *gizmo2;
    sendMouse(viewport, QEvent::MouseButtonPress, from2, Qt::LeftButton, Qt::LeftButton);
    sendMouse(viewport, QEvent::MouseMove, from2 + QPointF(-1.5, 0.5), Qt::NoButton, Qt::LeftButton);
    const quint64 dragged = renderer->generation();
    QTRY_VERIFY_WITH_TIMEOUT(renderer->latestPreview().generation == dragged, kTimeoutMs);
    qInfo("first frame of a drag after the selection: %s", qPrintable(renderer->latestPreview().lastUpdate));
    QVERIFY2(renderer->latestPreview().approximate && renderer->latestPreview().lastUpdate.contains("shadowField"),
             qPrintable(renderer->latestPreview().lastUpdate));
    sendMouse(viewport, QEvent::MouseButtonRelease, from2 + QPointF(-1.5, 0.5), Qt::LeftButton, Qt::NoButton);
    QTRY_VERIFY_WITH_TIMEOUT(renderer->latestPreview().generation == dragged && !renderer->latestPreview().approximate,
                             kTimeoutMs);
    const scene::Scene& final2 = *window.document()->scene();
    auto scratch3 = relight::RelightPreview::create(final2, RelightWorker::previewSettings(final2, kSize, kSize));
    QVERIFY(scratch3);
    QVERIFY(util::maxRelativeDifference(*renderer->latestPreview().image, (*scratch3)->image(kSize, kSize)) <= 1e-6);
}

QTEST_MAIN(ViewportRelightDragTest)
#include "viewport_relight_drag_test.moc"
