// Edits reach the render thread as change sets (architecture.md §5.B "What an edit rebuilds"):
// through the real window, document, undo stack, controller and worker, each edit kind (and its
// undo) updates the session in place, and the frame after it says what the update rebuilt and
// uploaded — a light drag re-sends the lights only, an object move refits the BVH, a camera or
// environment-rotation edit re-sends the parameters and never the geometry or the texels.
#include "app/editor_options.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"

#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kLoadTimeoutMs = 60000;
constexpr int kFrameTimeoutMs = 120000;

} // namespace

class EditorEditFlowTest : public QObject {
    Q_OBJECT
private slots:
    void everyEditKindUpdatesOnlyWhatItChanged();

private:
    // Applies `edit` (or, without one, undoes the last step), waits for its first frame and
    // returns the frame's update line.
    QString frameAfter(MainWindow& window, const std::optional<PropertyEdit>& edit);
};

QString EditorEditFlowTest::frameAfter(MainWindow& window, const std::optional<PropertyEdit>& edit) {
    RenderController* renderer = window.renderer();
    if (edit) {
        auto status = window.document()->apply(*edit);
        if (!status) return QString::fromStdString("edit failed: " + status.error().message());
    } else {
        window.document()->undoStack()->undo();
    }
    const quint64 generation = renderer->generation();
    const bool arrived = QTest::qWaitFor(
        [&] {
            return (renderer->latestFrame().generation == generation &&
                    renderer->latestFrame().samplesPerPixel >= 1) ||
                   window.errors()->count() > 0;
        },
        kFrameTimeoutMs);
    if (!arrived || window.errors()->count() > 0) return "no frame: " + window.errors()->lastMessage();
    return renderer->latestFrame().lastUpdate;
}

void EditorEditFlowTest::everyEditKindUpdatesOnlyWhatItChanged() {
    RenderSettings settings;
    settings.width = 32;
    settings.height = 32;
    settings.device = render::DeviceChoice::Vulkan;
    settings.sampler = render::SamplerKind::Bsdf; // no sampler tables: the counts are the scene's
    settings.maxSamplesPerPixel = 1;
    settings.validation = true;
    MainWindow window(settings);
    window.show();
    window.document()->open(defaultScenePath());
    QTRY_VERIFY_WITH_TIMEOUT(window.document()->scene() || window.errors()->count() > 0, kLoadTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->latestFrame().samplesPerPixel >= 1 ||
                                 window.errors()->count() > 0,
                             kFrameTimeoutMs);
    QVERIFY2(window.errors()->count() == 0, qPrintable(window.errors()->lastMessage()));
    // The first frame of an opened scene: everything built and sent once.
    QVERIFY2(window.renderer()->latestFrame().lastUpdate.contains("bvh built 1"),
             qPrintable(window.renderer()->latestFrame().lastUpdate));

    const scene::Scene& s = *window.document()->scene();
    using scene::EntityKind;
    const EntityRef light{EntityKind::Light, s.lighting.lights.front().id};
    const EntityRef material{EntityKind::Material, s.materials.front().id};
    const EntityRef object{EntityKind::Object, s.objects.front().id};
    const EntityRef env{EntityKind::Environment, scene::kInvalidId};
    const EntityRef camera{EntityKind::Camera, scene::kInvalidId};

    QCOMPARE(frameAfter(window, PropertyEdit{light, "intensity", 90.0f}), QString("uploaded: lights"));
    QCOMPARE(frameAfter(window, std::nullopt), QString("uploaded: lights")); // its undo
    QCOMPARE(frameAfter(window, PropertyEdit{material, "roughness", 0.5f}), QString("uploaded: materials"));
    QCOMPARE(frameAfter(window, PropertyEdit{object, "translation", glm::vec3(0.2f, 0.12f, 0.0f)}),
             QString("rebuilt: bvh refit 1; uploaded: geometry"));
    QCOMPARE(frameAfter(window, std::nullopt), QString("rebuilt: bvh refit 1; uploaded: geometry"));
    QCOMPARE(frameAfter(window, PropertyEdit{env, "rotation", 45.0f}), QString("uploaded: params"));
    QCOMPARE(frameAfter(window, PropertyEdit{env, "intensity", 1.5f}), QString("uploaded: params"));
    QCOMPARE(frameAfter(window, PropertyEdit{camera, "position", glm::vec3(0.0f, 1.8f, 3.4f)}),
             QString("uploaded: params"));
    QCOMPARE(window.renderer()->latestFrame().validationMessages, 0);
}

QTEST_MAIN(EditorEditFlowTest)
#include "editor_edit_flow_test.moc"
