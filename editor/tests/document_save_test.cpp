// The open document as an artist uses it, on the real editor (offscreen): edits of a scene's
// referenced lighting setup survive Save As and reopening while the shared setup stays
// byte-identical; Save writes the scene and the setup; separate edits undo one at a time and a
// slider drag in one step, with the step named in the Edit menu; entities are named `kind:name`;
// the title carries a modified marker and closing asks "Save changes?".
#include "app/editor_actions.h"
#include "app/editor_options.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "app/unsaved_changes_prompt.h"
#include "panels/outline_panel.h"
#include "panels/property_panel.h"
#include "scripting/script_api.h"
#include "document_test_settings.h"

#include "scene/scene_io.h"

#include <QAbstractButton>
#include <QAction>
#include <QCryptographicHash>
#include <QDoubleSpinBox>
#include <QJSEngine>
#include <QMessageBox>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kTimeoutMs = kDocumentTimeoutMs;

QString resource(const QString& relative) {
    return QFileInfo(defaultScenePath()).dir().filePath("../" + relative);
}

QByteArray digest(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256);
}

bool openAndWait(MainWindow& window, const QString& path) {
    QSignalSpy opened(window.document(), &SceneDocument::sceneOpened);
    window.document()->open(path);
    return opened.wait(kTimeoutMs) || opened.count() > 0;
}

bool saveAndWait(SceneDocument* document, const std::function<void()>& start) {
    QSignalSpy saved(document, &SceneDocument::saved);
    QSignalSpy failed(document, &SceneDocument::saveFailed);
    start();
    QDeadlineTimer deadline(kTimeoutMs);
    while (saved.count() + failed.count() == 0 && !deadline.hasExpired()) QTest::qWait(10);
    return saved.count() == 1;
}

// The light named `name` in a scene.
const scene::Light* lightNamed(const scene::Scene& s, const std::string& name) {
    for (const auto& l : s.lighting.lights)
        if (l.name == name) return &l;
    return nullptr;
}

// The `app` object scripts see, on this window, with its errors readable.
struct Script {
    explicit Script(MainWindow* window) : api(new AppApi(window, &engine)) {}
    QString takeError() {
        if (!engine.hasError()) return {};
        return engine.catchError().toString();
    }
    QJSEngine engine;
    AppApi* api;
};

} // namespace

class DocumentSaveTest : public QObject {
    Q_OBJECT
private slots:
    void referencedLightingEditsSurviveSaveAs();
    void saveWritesSceneAndSetup();
    void separateEditsUndoAloneAndADragUndoesWhole();
    void entitiesByKindAndName();
    void modifiedMarkerAndSaveChangesPrompt();
    void unknownBrdfAndTypoKeysAreRefused();
};

void DocumentSaveTest::referencedLightingEditsSurviveSaveAs() {
    const QString sharedSetup = resource("lighting/sun_sky.wllight");
    const QByteArray sharedBefore = digest(sharedSetup);
    QVERIFY(!sharedBefore.isEmpty());
    QTemporaryDir dir;
    MainWindow window(documentTestSettings());
    QVERIFY(openAndWait(window, resource("scenes/glossy_sphere.wlscene")));
    SceneDocument* document = window.document();
    QCOMPARE(document->scene()->lightingPath, std::string("../lighting/sun_sky.wllight"));
    QVERIFY(!document->isModified());
    QCOMPARE(document->defaultLightingSave(), LightingSave::Reference);

    Script script(&window);
    QVERIFY(script.api->setProperty("light:sun", "intensity", QJSValue(9.5)));
    QVERIFY(script.api->setProperty("environment", "rotation", QJSValue(75.0)));
    QCOMPARE(script.takeError(), QString());
    QVERIFY(document->isModified());
    QVERIFY(document->lightingEdited());
    QCOMPARE(document->defaultLightingSave(), LightingSave::Copy);

    // Save As with the default: the scene and a copy of the edited setup beside it.
    const QString copied = dir.filePath("relit.wlscene");
    QVERIFY(script.api->saveScene(copied));
    QCOMPARE(script.takeError(), QString());
    QCOMPARE(digest(sharedSetup), sharedBefore); // the shared setup is untouched
    QVERIFY(QFileInfo::exists(dir.filePath("relit.wllight")));
    QVERIFY(!document->isModified());
    auto reopened = scene::loadScene(copied.toStdString());
    QVERIFY2(reopened.ok(), reopened.ok() ? "" : reopened.error().message().c_str());
    QCOMPARE(reopened->lightingPath, std::string("relit.wllight"));
    QCOMPARE(lightNamed(*reopened, "sun")->intensity, 9.5f);
    QCOMPARE(reopened->lighting.environment.rotationDeg, 75.0f);
    QVERIFY(reopened->lighting.environment.image); // the map path was re-expressed for the copy
    QCOMPARE(reopened->objects.size(), document->scene()->objects.size());

    // Keeping the reference would drop edits: refused, naming the setup.
    QVERIFY(script.api->setProperty("light:sun", "intensity", QJSValue(4.0)));
    QVERIFY(!script.api->saveScene(dir.filePath("lost.wlscene"), "reference"));
    QVERIFY(script.takeError().contains("relit.wllight"));
    QVERIFY(!QFileInfo::exists(dir.filePath("lost.wlscene")));

    // The same edits inline, into another folder.
    QVERIFY(QDir(dir.path()).mkpath("inline"));
    const QString inlined = dir.filePath("inline/relit.wlscene");
    QVERIFY(script.api->setProperty("light:sun", "intensity", QJSValue(3.25)));
    QVERIFY(script.api->saveScene(inlined, "inline"));
    QCOMPARE(script.takeError(), QString());
    auto inlineScene = scene::loadScene(inlined.toStdString());
    QVERIFY2(inlineScene.ok(), inlineScene.ok() ? "" : inlineScene.error().message().c_str());
    QVERIFY(inlineScene->lightingPath.empty());
    QCOMPARE(lightNamed(*inlineScene, "sun")->intensity, 3.25f);
    QVERIFY(inlineScene->lighting.environment.image);
    QCOMPARE(digest(sharedSetup), sharedBefore);

}

void DocumentSaveTest::saveWritesSceneAndSetup() {
    QTemporaryDir dir;
    MainWindow window(documentTestSettings());
    QVERIFY(openAndWait(window, resource("scenes/glossy_sphere.wlscene")));
    SceneDocument* document = window.document();
    const EntityRef sun{scene::EntityKind::Light, lightNamed(*document->scene(), "sun")->id};
    QVERIFY(document->apply({sun, "intensity", 7.0f}).ok());
    const QString scenePath = dir.filePath("mine.wlscene");
    QVERIFY(saveAndWait(document, [&] { document->saveAs(scenePath); }));
    const QString setupPath = dir.filePath("mine.wllight");
    const QByteArray sceneBefore = digest(scenePath), setupBefore = digest(setupPath);

    // Save (Ctrl+S) after a lighting edit and a material edit: both files are rewritten.
    const EntityRef chrome{scene::EntityKind::Material, document->scene()->materials.front().id};
    QVERIFY(document->apply({sun, "intensity", 2.5f}).ok());
    QVERIFY(document->apply({chrome, "roughness", 0.375f}).ok());
    QVERIFY(saveAndWait(document, [&] { window.actions()->action("actionSaveScene")->trigger(); }));
    QVERIFY(digest(setupPath) != setupBefore);
    QVERIFY(digest(scenePath) != sceneBefore);
    auto setup = scene::loadLightingSetup(setupPath.toStdString());
    QVERIFY2(setup.ok(), setup.ok() ? "" : setup.error().message().c_str());
    QCOMPARE(setup->lights.front().intensity, 2.5f);
    auto saved = scene::loadScene(scenePath.toStdString());
    QVERIFY(saved.ok());
    QCOMPARE(saved->materials.front().roughness, 0.375f);
    QCOMPARE(lightNamed(*saved, "sun")->intensity, 2.5f);
    QVERIFY(!document->isModified());

    // A save that cannot write the setup leaves the scene file as it was and says why.
    QVERIFY(document->apply({sun, "intensity", 1.0f}).ok());
    const QByteArray sceneNow = digest(scenePath);
    QFile::remove(setupPath);
    QVERIFY(QDir(dir.path()).mkdir("mine.wllight")); // a folder where the file must go
    window.errors()->setDialogsEnabled(false);
    QVERIFY(!saveAndWait(document, [&] { document->save(); }));
    QVERIFY2(window.errors()->lastMessage().contains("mine.wllight"), qPrintable(window.errors()->lastMessage()));
    QCOMPARE(digest(scenePath), sceneNow);
    QVERIFY(document->isModified());
}

void DocumentSaveTest::separateEditsUndoAloneAndADragUndoesWhole() {
    MainWindow window(documentTestSettings());
    QVERIFY(openAndWait(window, resource("scenes/glossy_sphere.wlscene")));
    SceneDocument* document = window.document();
    QUndoStack* undo = document->undoStack();
    Script script(&window);

    // Three separate script edits of one property, two separate camera moves: five steps.
    for (double r : {0.2, 0.3, 0.4}) QVERIFY(script.api->setProperty("material:chrome", "roughness", QJSValue(r)));
    const scene::Camera camera = document->scene()->camera;
    QJSValue p1 = script.engine.newArray(3), p2 = script.engine.newArray(3);
    for (quint32 i = 0; i < 3; ++i) {
        p1.setProperty(i, camera.position[int(i)] + 0.5);
        p2.setProperty(i, camera.position[int(i)] + 1.0);
    }
    QVERIFY(script.api->setProperty("camera", "position", p1));
    QVERIFY(script.api->setProperty("camera", "position", p2));
    QCOMPARE(undo->count(), 5);
    QAction* undoAction = window.actions()->action("actionUndo");
    QCOMPARE(undoAction->text(), QString("&Undo camera position"));
    undoAction->trigger();
    QCOMPARE(document->scene()->camera.position, camera.position + glm::vec3(0.5f));
    undoAction->trigger();
    QCOMPARE(document->scene()->camera.position, camera.position);
    QCOMPARE(undoAction->text(), QString("&Undo chrome roughness"));
    undoAction->trigger();
    QCOMPARE(document->scene()->materials.front().roughness, 0.3f);

    // One slider drag in the property panel: one step, named after the light and property.
    const scene::Light* sun = lightNamed(*document->scene(), "sun");
    QVERIFY(window.outline()->select({scene::EntityKind::Material, document->scene()->materials.front().id}));
    QWidget* row = window.properties()->editorFor("roughness");
    QVERIFY(row);
    auto* slider = row->findChild<QSlider*>("slider");
    QVERIFY(slider);
    const int before = undo->index();
    slider->setSliderDown(true);
    for (int position : {500, 600, 700, 800}) slider->setValue(position);
    slider->setSliderDown(false);
    QCOMPARE(undo->index(), before + 1);
    QCOMPARE(document->scene()->materials.front().roughness, 0.8f);
    undoAction->trigger();
    QCOMPARE(document->scene()->materials.front().roughness, 0.3f); // the whole drag at once

    QVERIFY(script.api->setProperty("light:sun", "intensity", QJSValue(double(sun->intensity) * 2.0)));
    QCOMPARE(undoAction->text(), QString("&Undo sun intensity"));
}

void DocumentSaveTest::entitiesByKindAndName() {
    MainWindow window(documentTestSettings());
    QVERIFY(openAndWait(window, resource("scenes/glossy_sphere.wlscene")));
    Script script(&window);
    // glossy_sphere has a material and an object both called "ground".
    QVERIFY(!script.api->setProperty("ground", "roughness", QJSValue(0.5)));
    const QString ambiguity = script.takeError();
    QVERIFY2(ambiguity.contains("material:ground") && ambiguity.contains("object:ground"), qPrintable(ambiguity));

    QVERIFY(script.api->setProperty("material:ground", "roughness", QJSValue(0.625)));
    QJSValue moved = script.engine.newArray(3);
    for (quint32 i = 0; i < 3; ++i) moved.setProperty(i, i == 1 ? -0.25 : 0.0);
    QVERIFY(script.api->setProperty("object:ground", "translation", moved));
    QCOMPARE(script.takeError(), QString());
    const auto s = window.document()->scene();
    for (const auto& m : s->materials)
        if (m.name == "ground") QCOMPARE(m.roughness, 0.625f);
    for (const auto& o : s->objects)
        if (o.name == "ground") QCOMPARE(o.transform.translation.y, -0.25f);
    QCOMPARE(script.api->getProperty("material:ground", "roughness").toNumber(), 0.625);
    QVERIFY(script.api->select("object:ground"));
    QVERIFY(window.properties()->title().contains("object"));
    QVERIFY(!script.api->select("ground"));
    QVERIFY(script.takeError().contains("ambiguous"));
}

void DocumentSaveTest::modifiedMarkerAndSaveChangesPrompt() {
    QTemporaryDir dir;
    auto window = std::make_unique<MainWindow>(documentTestSettings());
    window->show();
    QVERIFY(openAndWait(*window, resource("scenes/glossy_sphere.wlscene")));
    Script script(window.get());
    QCOMPARE(script.api->windowTitle(), QString("glossy_sphere.wlscene — Wavelit"));
    QVERIFY(script.api->setProperty("material:chrome", "roughness", QJSValue(0.5)));
    QVERIFY(script.api->isModified());
    QCOMPARE(script.api->windowTitle(), QString("glossy_sphere.wlscene* — Wavelit"));
    window->actions()->action("actionUndo")->trigger();
    QCOMPARE(script.api->windowTitle(), QString("glossy_sphere.wlscene — Wavelit")); // back to clean
    window->actions()->action("actionRedo")->trigger();
    QVERIFY(window->isWindowModified());

    // Quit asks; Cancel keeps the window and the edits.
    UnsavedChangesPrompt* prompt = window->actions()->prompt();
    window->actions()->action("actionQuit")->trigger();
    QTRY_VERIFY(prompt->currentDialog() != nullptr);
    QCOMPARE(prompt->currentDialog()->objectName(), QString("saveChangesDialog"));
    prompt->currentDialog()->button(QMessageBox::Cancel)->click();
    QTRY_VERIFY(prompt->currentDialog() == nullptr);
    QVERIFY(window->isVisible());
    QVERIFY(window->document()->isModified());

    // A scripted answer: "save" writes the document (to where it was saved as), then closes.
    const QString path = dir.filePath("prompted.wlscene");
    QVERIFY(script.api->saveScene(path));
    QVERIFY(script.api->setProperty("material:chrome", "roughness", QJSValue(0.25)));
    QVERIFY(script.api->answerPrompts("save"));
    window->actions()->action("actionQuit")->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!window->isVisible(), kTimeoutMs);
    auto saved = scene::loadScene(path.toStdString());
    QVERIFY(saved.ok());
    QCOMPARE(saved->materials.front().roughness, 0.25f);
    QCOMPARE(prompt->timesAsked(), 2);

    // "discard" closes without writing.
    auto second = std::make_unique<MainWindow>(documentTestSettings());
    second->show();
    QVERIFY(openAndWait(*second, path));
    Script other(second.get());
    QVERIFY(other.api->setProperty("material:chrome", "roughness", QJSValue(0.75)));
    QVERIFY(other.api->answerPrompts("discard"));
    second->close();
    QTRY_VERIFY(!second->isVisible());
    QCOMPARE(scene::loadScene(path.toStdString())->materials.front().roughness, 0.25f);
    QVERIFY(!other.api->answerPrompts("maybe"));
    QVERIFY(other.takeError().contains("maybe"));
}


void DocumentSaveTest::unknownBrdfAndTypoKeysAreRefused() {
    MainWindow window(documentTestSettings());
    window.show();
    const QString glossy = resource("scenes/glossy_sphere.wlscene");
    QVERIFY(openAndWait(window, glossy));
    Script script(&window);
    QVERIFY(!script.api->setProperty("material:chrome", "brdf", QJSValue("no_such_brdf")));
    const QString refused = script.takeError();
    QVERIFY2(refused.contains("no_such_brdf") && refused.contains("lambert") && refused.contains("ggx"),
             qPrintable(refused));
    QVERIFY(!script.api->isModified());

    // Files with problems: a dialog lists them and the open document stays.
    const QDir bad(QFileInfo(defaultScenePath()).dir().filePath("../../tests/data/bad"));
    struct Case { const char* file; QStringList mentions; };
    for (const Case& c : {Case{"unknown_brdf.wlscene", {"ground", "no_such_brdf", "lambert"}},
                          Case{"typo_key.wlscene", {"roughnes", "did you mean 'roughness'"}}}) {
        const int errorsBefore = window.errors()->count();
        window.document()->open(bad.filePath(c.file));
        QTRY_VERIFY_WITH_TIMEOUT(window.errors()->count() > errorsBefore, kTimeoutMs);
        QVERIFY(window.errors()->currentDialog());
        const QString text = window.errors()->currentDialog()->text();
        QVERIFY2(text.contains(c.file), qPrintable(text));
        for (const QString& m : c.mentions) QVERIFY2(text.contains(m), qPrintable(text));
        window.errors()->currentDialog()->accept();
        QCOMPARE(window.document()->path(), glossy);
        QVERIFY(window.document()->scene());
    }
}

QTEST_MAIN(DocumentSaveTest)
#include "document_save_test.moc"
