// File -> Render to file's progress dialog (issue 14): a render with a budget far beyond the test
// shows a progress dialog that advances (the bar's value and its "N spp" text), and a click on its
// Cancel button stops the render within seconds, reports "cancelled" and writes no file. Then a
// small budget renders to completion through the same path and the file appears.
// A render's `finished` that arrives while the modal dialog's setValue() processes events (it
// does, being modal) closes the dialog without a crash: CI once saw a segfault there.
#include "app/file_actions.h"
#include "app/main_window.h"
#include "app/scene_document.h"

#include <QFileInfo>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

using namespace wavelit;
using namespace wavelit::editor;

constexpr int kTimeoutMs = 240000;

// A 32^2 viewport, one `bsdf` pass: the window's own renderer stays out of the way.
RenderSettings smallBsdfSettings() {
    RenderSettings settings;
    settings.width = 32;
    settings.height = 32;
    settings.sampler = render::SamplerKind::Bsdf;
    settings.maxSamplesPerPixel = 1;
    settings.validation = qEnvironmentVariableIntValue("WAVELIT_VK_VALIDATION") == 1;
    return settings;
}

class FilesRenderCancelTest : public QObject {
    Q_OBJECT
private slots:
    void cancelStopsAndWritesNothing();
    void finishedInsideAProgressUpdate();
};

void FilesRenderCancelTest::cancelStopsAndWritesNothing() {
    MainWindow window(smallBsdfSettings());
    window.show();
    window.document()->open(QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/ring_on_ground.wlscene"));
    QVERIFY(QTest::qWaitFor([&] { return window.document()->scene() != nullptr; }, kTimeoutMs));
    QTemporaryDir dir;
    const QString path = dir.filePath("cancelled.exr");

    QString result = "not finished";
    window.files()->renderToFile(path, {1 << 20, 0.0}, true, [&](const QString& error) { result = error; });
    auto* dialog = window.findChild<QProgressDialog*>("renderProgress");
    QVERIFY(dialog);
    QVERIFY(QTest::qWaitFor([&] { return dialog->value() > 0 || dialog->labelText().contains("spp"); }, kTimeoutMs));
    qInfo("progress before cancel: %s", qPrintable(dialog->labelText()));
    QPushButton* cancel = dialog->findChild<QPushButton*>();
    QVERIFY(cancel);
    QElapsedTimer clock;
    clock.start();
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(QTest::qWaitFor([&] { return result != "not finished"; }, kTimeoutMs));
    qInfo("cancelled after %lld ms", clock.elapsed());
    QCOMPARE(result, QStringLiteral("cancelled"));
    QVERIFY(!QFileInfo::exists(path));
    QVERIFY(!window.files()->fileRender()->isRunning());

    const QString done = dir.filePath("done.exr");
    result = "not finished";
    window.files()->renderToFile(done, {2, 0.0}, true, [&](const QString& error) { result = error; });
    QVERIFY(QTest::qWaitFor([&] { return result != "not finished"; }, kTimeoutMs));
    QCOMPARE(result, QString());
    QVERIFY(QFileInfo::exists(done));
}

// The order that crashed, made certain: `finished` is queued first, then a progress update runs
// synchronously, and the modal dialog's setValue() delivers the queued `finished` inside it.
void FilesRenderCancelTest::finishedInsideAProgressUpdate() {
    MainWindow window(smallBsdfSettings());
    window.show();
    window.document()->open(QStringLiteral(WAVELIT_RESOURCE_DIR "/scenes/ring_on_ground.wlscene"));
    QVERIFY(QTest::qWaitFor([&] { return window.document()->scene() != nullptr; }, kTimeoutMs));
    QTemporaryDir dir;
    const QString path = dir.filePath("long.exr");
    QString result = "not finished";
    window.files()->renderToFile(path, {1 << 20, 0.0}, true, [&](const QString& error) { result = error; });
    QPointer<QProgressDialog> dialog = window.findChild<QProgressDialog*>("renderProgress");
    QVERIFY(dialog);
    QVERIFY(QTest::qWaitFor([&] { return dialog->isVisible() && dialog->labelText().contains("spp"); }, kTimeoutMs));

    RenderToFile* render = window.files()->fileRender();
    emit render->progress(0.25, QStringLiteral("a first value above the minimum: the dialog counts as shown"));
    QMetaObject::invokeMethod(render, [&] { emit render->finished(path, QStringLiteral("cancelled")); },
                              Qt::QueuedConnection);
    emit render->progress(0.5, QStringLiteral("update that runs the event loop"));
    QCOMPARE(result, QStringLiteral("cancelled")); // delivered inside setValue()
    QVERIFY(QTest::qWaitFor([&] { return dialog.isNull(); }, kTimeoutMs));

    render->cancel(); // the real render, still running, stops; its own finished finds no dialog
    QVERIFY(QTest::qWaitFor([&] { return !render->isRunning(); }, kTimeoutMs));
    QVERIFY(!QFileInfo::exists(path));
}

QTEST_MAIN(FilesRenderCancelTest)
#include "files_render_cancel_test.moc"
