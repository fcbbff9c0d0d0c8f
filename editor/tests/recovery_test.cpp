// No crash loses work (issue 15), on the real editor (offscreen): edits are autosaved to a recovery
// file; a window that dies without saving leaves it; the next window that opens the scene offers
// it, and recovering restores the edits — referenced lighting still referenced, the document
// modified — while saving or discarding removes it. A save into a folder that vanished, or into a
// read-only one, reports the error, keeps the edits and leaves the old file byte-identical.
#include "app/autosave_controller.h"
#include "app/editor_options.h"
#include "app/error_reporter.h"
#include "app/main_window.h"
#include "app/scene_document.h"
#include "scripting/script_api.h"
#include "document_test_settings.h"

#include "scene/scene_io.h"

#include <QJSEngine>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <unistd.h>

using namespace wavelit;
using namespace wavelit::editor;

namespace {

constexpr int kTimeoutMs = kDocumentTimeoutMs;

struct Editor {
    Editor() : window(documentTestSettings()), api(new AppApi(&window, &engine)) {
        window.errors()->setDialogsEnabled(false);
    }
    bool open(const QString& path) {
        QSignalSpy opened(window.document(), &SceneDocument::sceneOpened);
        window.document()->open(path);
        return opened.wait(kTimeoutMs) || opened.count() > 0;
    }
    QString takeError() { return engine.hasError() ? engine.catchError().toString() : QString(); }
    float sunIntensity() const {
        for (const auto& l : window.document()->scene()->lighting.lights)
            if (l.name == "sun") return l.intensity;
        return -1.0f;
    }
    MainWindow window;
    QJSEngine engine;
    AppApi* api;
};

} // namespace

class RecoveryTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void editsSurviveACrash();
    void discardedRecoveryIsGone();
    void saveIntoVanishedFolderKeepsEdits();
    void saveIntoReadOnlyFolderKeepsTheOriginal();

private:
    QTemporaryDir m_dir;
    QString m_scene;
};

void RecoveryTest::initTestCase() {
    QVERIFY(m_dir.isValid());
    qputenv("WAVELIT_RECOVERY_DIR", m_dir.filePath("recovery").toUtf8());
    qputenv("WAVELIT_AUTOSAVE_MS", "50");
    // A scene of our own that refers to the bundled sun_sky setup.
    Editor editor;
    QVERIFY(editor.open(QFileInfo(defaultScenePath()).dir().filePath("glossy_sphere.wlscene")));
    m_scene = m_dir.filePath("scene.wlscene");
    QVERIFY(editor.api->saveScene(m_scene));
    QCOMPARE(editor.takeError(), QString());
    QTest::qWait(20); // the recovery must be newer than the file
}

void RecoveryTest::editsSurviveACrash() {
    {
        Editor first;
        QVERIFY(first.open(m_scene));
        QCOMPARE(first.api->recoveryFile(), QString());
        QSignalSpy autosaved(first.window.autosave(), &AutosaveController::autosaved);
        QVERIFY(first.api->setProperty("light:sun", "intensity", QJSValue(8.0)));
        QVERIFY(first.api->setProperty("material:chrome", "roughness", QJSValue(0.3)));
        // By the timer. (The file is on disk a moment before the signal is delivered, so wait for
        // the signal, not for the file.)
        QTRY_VERIFY_WITH_TIMEOUT(autosaved.count() >= 1, kTimeoutMs);
        QVERIFY(!first.api->recoveryFile().isEmpty());
        QVERIFY(first.api->setProperty("camera", "fov", QJSValue(35.0)));
        QVERIFY(first.api->autosave()); // and on request
        // The window dies here without closing: nothing asks, nothing is saved.
    }
    QVERIFY(QFileInfo::exists(RecoveryStore().recoveryFileFor(m_scene)));

    Editor second;
    QVERIFY(second.api->answerRecovery("recover"));
    QSignalSpy recovered(second.window.autosave(), &AutosaveController::recovered);
    QVERIFY(second.open(m_scene));
    QTRY_VERIFY_WITH_TIMEOUT(recovered.count() == 1, kTimeoutMs);
    SceneDocument* document = second.window.document();
    QCOMPARE(document->path(), m_scene);
    QVERIFY(document->isModified());
    QCOMPARE(second.sunIntensity(), 8.0f);
    QCOMPARE(document->scene()->materials.front().roughness, 0.3f);
    QCOMPARE(document->scene()->camera.verticalFovDeg, 35.0f);
    // Still a reference to the shared setup, whose edits are the document's.
    auto onDisk = scene::loadScene(m_scene.toStdString());
    QVERIFY(onDisk.ok());
    QCOMPARE(document->scene()->lightingPath, onDisk->lightingPath);
    QVERIFY(document->lightingEdited());
    QVERIFY(document->scene()->lighting.environment.image);

    // Saving (here as a copy, the shared setup untouched) removes the recovery.
    QVERIFY(second.api->saveScene(m_scene, "copy"));
    QCOMPARE(second.takeError(), QString());
    QVERIFY(!document->isModified());
    QCOMPARE(second.api->recoveryFile(), QString());
    QVERIFY(!QFileInfo::exists(RecoveryStore().recoveryFileFor(m_scene)));
    auto saved = scene::loadScene(m_scene.toStdString());
    QVERIFY(saved.ok());
    QCOMPARE(saved->materials.front().roughness, 0.3f);
}

void RecoveryTest::discardedRecoveryIsGone() {
    {
        Editor first;
        QVERIFY(first.open(m_scene));
        QVERIFY(first.api->setProperty("material:chrome", "roughness", QJSValue(0.9)));
        QVERIFY(first.api->autosave());
    }
    Editor second;
    QVERIFY(second.api->answerRecovery("keep"));
    QVERIFY(second.open(m_scene));
    QVERIFY(!second.window.document()->isModified());
    QVERIFY(!second.api->recoveryFile().isEmpty()); // kept for later

    Editor third;
    QVERIFY(third.api->answerRecovery("discard"));
    QVERIFY(third.open(m_scene));
    QVERIFY(!third.window.document()->isModified());
    QCOMPARE(third.window.document()->scene()->materials.front().roughness, 0.3f);
    QCOMPARE(third.api->recoveryFile(), QString());
    QVERIFY(!third.api->answerRecovery("perhaps"));
    QVERIFY(third.takeError().contains("perhaps"));
}

void RecoveryTest::saveIntoVanishedFolderKeepsEdits() {
    Editor editor;
    QVERIFY(editor.open(m_scene));
    QVERIFY(editor.api->setProperty("material:chrome", "roughness", QJSValue(0.55)));
    QVERIFY(QDir(m_dir.path()).mkpath("vanishing"));
    const QString target = m_dir.filePath("vanishing/out.wlscene");
    QVERIFY(QDir(m_dir.filePath("vanishing")).removeRecursively());
    QVERIFY(!editor.api->saveScene(target));
    const QString error = editor.takeError();
    QVERIFY2(error.contains("out.wlscene"), qPrintable(error));
    QVERIFY(editor.window.document()->isModified());
    QCOMPARE(editor.window.document()->path(), m_scene);
    QVERIFY(!QFileInfo::exists(target));
}

// A folder nobody may write into. root ignores permission bits, so for root the folder is made
// immutable (chattr +i, ext4/xfs/btrfs); false where neither works.
bool makeReadOnly(const QString& folder, bool readOnly) {
    if (::geteuid() != 0)
        return QFile::setPermissions(folder, readOnly ? QFileDevice::ReadOwner | QFileDevice::ExeOwner
                                                      : QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                                                            QFileDevice::ExeOwner);
    return QProcess::execute("chattr", {readOnly ? "+i" : "-i", folder}) == 0;
}

void RecoveryTest::saveIntoReadOnlyFolderKeepsTheOriginal() {
    QVERIFY(QDir(m_dir.path()).mkpath("locked"));
    const QString folder = m_dir.filePath("locked");
    const QString path = folder + "/kept.wlscene";
    Editor editor;
    QVERIFY(editor.open(m_scene));
    QVERIFY(editor.api->saveScene(path));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray before = file.readAll();
    file.close();
    QVERIFY(editor.api->setProperty("material:chrome", "roughness", QJSValue(0.65)));
    if (!makeReadOnly(folder, true)) QSKIP("cannot make a read-only folder on this file system");
    const bool saved = editor.api->save();
    const QString error = editor.takeError();
    QVERIFY(makeReadOnly(folder, false));
    QVERIFY(!saved);
    QVERIFY2(error.contains("kept.wlscene"), qPrintable(error));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), before); // byte-identical
    QVERIFY(editor.window.document()->isModified());
    QCOMPARE(QDir(folder).entryList(QDir::Files), QStringList{"kept.wlscene"}); // no temp left
}

QTEST_MAIN(RecoveryTest)
#include "recovery_test.moc"
