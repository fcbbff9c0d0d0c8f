// The editor end to end on the offscreen platform: the default scene opens, the outline lists
// every entity, the render thread accumulates >= 8 spp into a viewport that is not blank,
// exposure changes only the display, and bad scene files end in an error dialog naming the file.
#include "app/editor_actions.h"
#include "app/editor_options.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "panels/outline_panel.h"
#include "panels/property_panel.h"
#include "viewport/viewport_widget.h"

#include <glm/geometric.hpp>

#include "scene/scene_io.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMessageBox>
#include <QSet>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

// lavapipe renders on the CPU, on a machine other builds share: generous, never a timing check.
constexpr int kRenderTimeoutMs = 240000;
constexpr int kLoadTimeoutMs = 60000;
constexpr int kRequiredSpp = 8;

RenderSettings testSettings() {
    RenderSettings settings;
    settings.width = 128;
    settings.height = 128;
    settings.maxSamplesPerPixel = 12; // stop using the CPU once the test has what it needs
    return settings;
}

struct ImageStats {
    int distinctColors = 0;
    double nonBackgroundFraction = 0.0;
    double meanLuminance = 0.0; // 8-bit units
};

ImageStats measure(const QImage& image, QRgb background) {
    QSet<QRgb> colors;
    qint64 nonBackground = 0;
    double luminance = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y) | 0xff000000u;
            colors.insert(p);
            if (p != background) ++nonBackground;
            luminance += 0.2126 * qRed(p) + 0.7152 * qGreen(p) + 0.0722 * qBlue(p);
        }
    const double n = double(image.width()) * image.height();
    return {int(colors.size()), double(nonBackground) / n, luminance / n};
}

QStringList namesOf(const auto& entities) {
    QStringList names;
    for (const auto& e : entities) names << QString::fromStdString(e.name);
    return names;
}

} // namespace

class EditorWindowTest : public QObject {
    Q_OBJECT
private slots:
    void rendersDefaultScene();
    void missingSceneShowsErrorNamingFile();
    void corruptSceneShowsErrorNamingFile();
    void renderDeviceFailureShowsError();
    void renderTooLargeShowsError();
    void panelEditRestartsRenderAndUndoes();
    void openingAnotherSceneReplacesRender();
    void saveAsWritesLoadableScene();
};

void EditorWindowTest::rendersDefaultScene() {
    RenderSettings settings = testSettings();
    settings.validation = true; // Vulkan validation layers on: any message fails the test
    MainWindow window(settings);
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.document()->scene() || window.errors()->count() > 0, kLoadTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    const auto scene = window.document()->scene();
    QVERIFY(!scene->objects.empty());
    QVERIFY(!scene->materials.empty());

    // Outline: every object, material and light by name, plus the environment.
    OutlinePanel* outline = window.outline();
    QCOMPARE(outline->namesUnder("Objects"), namesOf(scene->objects));
    QCOMPARE(outline->namesUnder("Materials"), namesOf(scene->materials));
    QCOMPARE(outline->namesUnder("Lighting"), QStringList{"Environment"} + namesOf(scene->lighting.lights));
    QVERIFY(!outline->tree()->findItems("Camera", Qt::MatchExactly).isEmpty());

    // Selecting a material shows its registry rows.
    QVERIFY(outline->select({scene::EntityKind::Material, scene->materials.front().id}));
    QVERIFY(window.properties()->title().startsWith(QString::fromStdString(scene->materials.front().name)));
    QVERIFY(window.properties()->table()->rowCount() >= 2);

    // Render: wait for >= 8 spp (or an error, reported with its message).
    ViewportWidget* viewport = window.viewport();
    QTRY_VERIFY_WITH_TIMEOUT(viewport->displayedSamplesPerPixel() >= kRequiredSpp ||
                                 window.errors()->count() > 0,
                             kRenderTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    QCOMPARE(viewport->displayedImage().size(), QSize(128, 128));
    QCOMPARE(window.renderer()->latestFrame().validationMessages, 0);
    auto* status = window.findChild<QLabel*>("renderStatus");
    QVERIFY(status);
    // spp · seconds · samples/s · sampler · noise (once estimated) · device (issue 14)
    QVERIFY2(status->text().contains(" spp") && status->text().contains("Msamples/s") &&
                 status->text().contains(" · wavelet") && status->text().count(QStringLiteral(" · ")) >= 4,
             qPrintable(status->text()));

    const QImage grabbed = viewport->grab().toImage();
    const QRgb background = grabbed.pixel(0, 0) | 0xff000000u; // letterbox corner
    const ImageStats stats = measure(grabbed, background);
    qInfo("viewport %dx%d at %d spp: %d colours, %.0f%% non-background, mean luminance %.1f; %s",
          grabbed.width(), grabbed.height(), viewport->displayedSamplesPerPixel(), stats.distinctColors,
          100.0 * stats.nonBackgroundFraction, stats.meanLuminance, qPrintable(status->text()));
    QVERIFY2(stats.distinctColors > 64, "the viewport looks blank");
    QVERIFY(stats.nonBackgroundFraction > 0.25);
    QVERIFY(stats.meanLuminance > 1.0);

    // Exposure is display-only: the image brightens, the render does not restart.
    const quint64 generation = window.renderer()->generation();
    const double before = measure(viewport->displayedImage(), 0).meanLuminance;
    window.actions()->action("actionExposureUp")->trigger();
    QCOMPARE(viewport->exposure(), scene->camera.exposureEv + EditorActions::kExposureStepEv);
    QCOMPARE(window.renderer()->generation(), generation);
    QVERIFY(viewport->displayedSamplesPerPixel() >= kRequiredSpp);
    // Re-mapped on the render thread: the brighter frame arrives shortly after.
    QTRY_VERIFY_WITH_TIMEOUT(measure(viewport->displayedImage(), 0).meanLuminance > before, kRenderTimeoutMs);

    // Dragging in the viewport orbits the camera: a Restart edit, so a new render generation
    // whose frames arrive from 1 spp again; the distance to the target is kept.
    const QPoint from = viewport->rect().center();
    QMouseEvent press(QEvent::MouseButtonPress, from, viewport->mapToGlobal(from), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &press);
    const QPoint to = from + QPoint(60, 20);
    QMouseEvent move(QEvent::MouseMove, to, viewport->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &move);
    QMouseEvent release(QEvent::MouseButtonRelease, to, viewport->mapToGlobal(to), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport, &release);
    const auto moved = window.document()->scene();
    QVERIFY(moved->camera.position != scene->camera.position);
    QCOMPARE(moved->camera.exposureEv, scene->camera.exposureEv + EditorActions::kExposureStepEv);
    const float distanceBefore = glm::length(scene->camera.position - scene->camera.target);
    const float distanceAfter = glm::length(moved->camera.position - moved->camera.target);
    QVERIFY(std::abs(distanceAfter - distanceBefore) < 1e-4f * distanceBefore); // float rounding
    QVERIFY(window.renderer()->generation() > generation);
    QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->latestFrame().samplesPerPixel >= 1 ||
                                 window.errors()->count() > 0,
                             kRenderTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));

    // Undo: the drag, then the exposure step, each one entry.
    window.actions()->action("actionUndo")->trigger();
    QCOMPARE(window.document()->scene()->camera.position, scene->camera.position);
    QCOMPARE(viewport->exposure(), scene->camera.exposureEv + EditorActions::kExposureStepEv);
    window.actions()->action("actionUndo")->trigger();
    QCOMPARE(viewport->exposure(), scene->camera.exposureEv);
    QVERIFY(!window.document()->undoStack()->canUndo());
    window.actions()->action("actionRedo")->trigger();
    QCOMPARE(window.document()->scene()->camera.exposureEv,
             scene->camera.exposureEv + EditorActions::kExposureStepEv);
}

void EditorWindowTest::missingSceneShowsErrorNamingFile() {
    MainWindow window(testSettings());
    window.show();
    window.document()->open("/nonexistent/folder/missing_scene.wlscene");
    QTRY_VERIFY_WITH_TIMEOUT(window.errors()->currentDialog() != nullptr, kLoadTimeoutMs);
    const QString text = window.errors()->currentDialog()->text();
    QVERIFY2(text.contains("missing_scene.wlscene"), qPrintable(text));
    QVERIFY(!window.document()->scene());
    window.errors()->currentDialog()->accept();
    QTRY_VERIFY(window.errors()->currentDialog() == nullptr);
}

void EditorWindowTest::corruptSceneShowsErrorNamingFile() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("corrupt.wlscene");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"format\": \"wavelit-scene\", \"version\": 1, \"objects\": [ {");
    file.close();

    MainWindow window(testSettings());
    window.show();
    window.document()->open(path);
    QTRY_VERIFY_WITH_TIMEOUT(window.errors()->currentDialog() != nullptr, kLoadTimeoutMs);
    const QString text = window.errors()->currentDialog()->text();
    QVERIFY2(text.contains("corrupt.wlscene"), qPrintable(text));
    QCOMPARE(window.errors()->count(), 1);
    QVERIFY(!window.document()->scene());
}

void EditorWindowTest::renderDeviceFailureShowsError() {
    // A Vulkan device that does not exist: the session fails on the render thread, the error
    // comes back as a signal and ends in a dialog; the window keeps working.
    qputenv("WAVELIT_VK_DEVICE", "no-such-gpu-for-editor-test");
    RenderSettings settings = testSettings();
    settings.device = render::DeviceChoice::Vulkan;
    MainWindow window(settings);
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.errors()->currentDialog() != nullptr, kRenderTimeoutMs);
    qunsetenv("WAVELIT_VK_DEVICE");
    const QString text = window.errors()->currentDialog()->text();
    QVERIFY2(text.contains("no-such-gpu-for-editor-test"), qPrintable(text));
    QVERIFY(window.document()->scene()); // the scene itself loaded fine
    QCOMPARE(window.viewport()->displayedSamplesPerPixel(), 0);
    QCOMPARE(window.findChild<QLabel*>("renderStatus")->text(), QString("render failed"));
}

void EditorWindowTest::renderTooLargeShowsError() {
    // A render size beyond the device's storage-buffer range (lavapipe: 128 MiB; 16384^2 needs a
    // 4 GiB accumulation buffer) is refused up front on the render thread (render_limits.h): the
    // dialog names the size, the limit and what to do; the scene stays open, nothing rendered.
    RenderSettings settings = testSettings();
    settings.device = render::DeviceChoice::Vulkan;
    settings.width = 16384;
    settings.height = 16384;
    MainWindow window(settings);
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.errors()->currentDialog() != nullptr, kRenderTimeoutMs);
    const QString text = window.errors()->currentDialog()->text();
    QVERIFY2(text.contains("the render size 16384x16384 is too big for"), qPrintable(text));
    QVERIFY2(text.contains("storage-buffer limit of") && text.contains("maxStorageBufferRange"),
             qPrintable(text));
    QVERIFY2(text.contains("render at a smaller size"), qPrintable(text));
    QVERIFY(window.document()->scene()); // the scene stays open
    QCOMPARE(window.viewport()->displayedSamplesPerPixel(), 0);
    QCOMPARE(window.findChild<QLabel*>("renderStatus")->text(), QString("render failed"));
}

void EditorWindowTest::panelEditRestartsRenderAndUndoes() {
    MainWindow window(testSettings());
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.document()->scene() || window.errors()->count() > 0, kLoadTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    const auto original = window.document()->scene();
    const scene::Material& material = original->materials.front();
    QVERIFY(window.outline()->select({scene::EntityKind::Material, material.id}));
    QWidget* roughnessRow = window.properties()->editorFor("roughness");
    QVERIFY(roughnessRow);
    auto* roughness = roughnessRow->findChild<QDoubleSpinBox*>("spin");
    QVERIFY(roughness);
    QCOMPARE(float(roughness->value()), material.roughness);

    const quint64 generation = window.renderer()->generation();
    const double newRoughness = material.roughness > 0.5f ? 0.1 : 0.9;
    roughness->setValue(newRoughness);
    QCOMPARE(window.document()->scene()->materials.front().roughness, float(newRoughness));
    QCOMPARE(window.renderer()->generation(), generation + 1); // a Restart edit
    QCOMPARE(window.properties()->editorFor("roughness"), roughnessRow);

    window.actions()->action("actionUndo")->trigger();
    QCOMPARE(window.document()->scene()->materials.front().roughness, material.roughness);
    QCOMPARE(float(roughness->value()), material.roughness);
    QCOMPARE(window.renderer()->generation(), generation + 2);
    QCOMPARE(window.errors()->count(), 0);
}

void EditorWindowTest::openingAnotherSceneReplacesRender() {
    MainWindow window(testSettings());
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.viewport()->displayedSamplesPerPixel() >= 1 ||
                                 window.errors()->count() > 0,
                             kRenderTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    const quint64 first = window.renderer()->generation();

    const QString other = QFileInfo(defaultScenePath()).dir().filePath("cornell_box.wlscene");
    window.document()->open(other);
    QTRY_VERIFY_WITH_TIMEOUT(window.document()->path() == other || window.errors()->count() > 0,
                             kLoadTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    const auto scene = window.document()->scene();
    QCOMPARE(window.outline()->namesUnder("Objects"), namesOf(scene->objects));
    QVERIFY(window.renderer()->generation() > first);
    // Only frames of the new scene reach the viewport once it restarted.
    QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->latestFrame().samplesPerPixel >= 1 ||
                                 window.errors()->count() > 0,
                             kRenderTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    QCOMPARE(window.renderer()->latestFrame().generation, window.renderer()->generation());
}

void EditorWindowTest::saveAsWritesLoadableScene() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window(testSettings());
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.document()->scene() || window.errors()->count() > 0, kLoadTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    const EntityRef gold{scene::EntityKind::Material, window.document()->scene()->materials.front().id};
    QVERIFY(window.document()->apply({gold, "roughness", 0.375f}).ok());

    // Into a folder that does not exist: an error naming the file, the document unchanged.
    const QString bad = dir.filePath("no/such/folder/out.wlscene");
    window.document()->saveAs(bad);
    QTRY_VERIFY_WITH_TIMEOUT(window.errors()->currentDialog() != nullptr, kLoadTimeoutMs);
    QVERIFY2(window.errors()->lastMessage().contains("out.wlscene"), qPrintable(window.errors()->lastMessage()));
    QCOMPARE(window.document()->path(), defaultScenePath());
    window.errors()->currentDialog()->accept();

    // Into another folder: asset paths are re-expressed relative to the new file.
    const QString good = dir.filePath("saved.wlscene");
    QSignalSpy saved(window.document(), &SceneDocument::saved);
    window.document()->saveAs(good);
    QTRY_COMPARE_WITH_TIMEOUT(saved.count() + window.errors()->count(), 2, kLoadTimeoutMs);
    QCOMPARE(saved.count(), 1);
    QCOMPARE(window.document()->path(), good);
    auto reloaded = scene::loadScene(good.toStdString());
    QVERIFY2(reloaded.ok(), reloaded.ok() ? "" : reloaded.error().message().c_str());
    QCOMPARE(reloaded->materials.front().roughness, 0.375f);
    QCOMPARE(namesOf(reloaded->objects), namesOf(window.document()->scene()->objects));
}

QTEST_MAIN(EditorWindowTest)
#include "editor_window_test.moc"
