// File-name checks as a save dialog closes (issue 14; app/save_file_dialog.h): Save scene as, Save
// lighting setup as and Render to file run SaveFileDialog, Qt's own dialog, which drives offscreen.
// The test opens each kind as the menu actions do (askSavePath builds the same dialog, run
// modally; here it is shown non-modally so the test can type into it), types a bad name and
// presses Save: the dialog stays open and a message box over it names the problem — a wrong
// extension, a missing folder, a folder that cannot be written. A good name closes it with that
// path; a name without an extension gets the filter's.
#include "app/save_file_dialog.h"

#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QtTest>

using namespace wavelit::editor;

class FilesSaveDialogTest : public QObject {
    Q_OBJECT
private slots:
    void problemsAreNamed();
    void dialogStaysOpenOnABadName();
    void dialogAddsTheFiltersExtension();

private:
    // An unwritable folder: /proc refuses new files even to root; otherwise a folder without write permission.
    QString unwritableFolder(QTemporaryDir& dir) {
        if (QFileInfo("/proc/self").exists()) return QStringLiteral("/proc");
        const QString path = dir.filePath("readonly");
        QDir().mkpath(path);
        QFile::setPermissions(path, QFile::ReadOwner | QFile::ExeOwner);
        return path;
    }
};

void FilesSaveDialogTest::problemsAreNamed() {
    QTemporaryDir dir;
    const QStringList render{"exr", "png"};
    QCOMPARE(outputPathProblem(dir.filePath("out.exr"), render), QString());
    QCOMPARE(outputPathProblem(dir.filePath("OUT.PNG"), render), QString());
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty()); // the write probe is gone
    const QString ext = outputPathProblem(dir.filePath("out.jpg"), render);
    qInfo("wrong extension: %s", qPrintable(ext));
    QVERIFY(ext.contains("out.jpg") && ext.contains(".exr or .png") && ext.contains("not .jpg"));
    const QString none = outputPathProblem(dir.filePath("out"), {"wlscene"});
    QVERIFY(none.contains(".wlscene"));
    const QString missing = outputPathProblem(dir.filePath("no/such/folder/out.exr"), render);
    qInfo("missing folder: %s", qPrintable(missing));
    QVERIFY(missing.contains("does not exist") && missing.contains("no/such/folder"));
    const QString folder = unwritableFolder(dir);
    const QString unwritable = outputPathProblem(folder + "/out.wllight", {"wllight"});
    qInfo("unwritable folder: %s", qPrintable(unwritable));
    QVERIFY(unwritable.contains("cannot be written") && unwritable.contains(folder));
    QVERIFY(outputPathProblem(dir.path(), render).contains("is a folder"));
}

void FilesSaveDialogTest::dialogStaysOpenOnABadName() {
    QTemporaryDir dir;
    struct Case { SaveTarget target; QString bad; QString good; QString says; };
    const QList<Case> cases = {
        {SaveTarget::Render, dir.filePath("image.jpg"), dir.filePath("image.png"), "extension"},
        {SaveTarget::Scene, dir.filePath("missing/scene.wlscene"), dir.filePath("scene.wlscene"), "does not exist"},
        {SaveTarget::Lighting, unwritableFolder(dir) + "/setup.wllight", dir.filePath("setup.wllight"), "cannot be written"},
    };
    for (const Case& c : cases) {
        SaveFileDialog dialog(nullptr, c.target, dir.path());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto* name = dialog.findChild<QLineEdit*>("fileNameEdit");
        QVERIFY(name);
        name->setText(c.bad); // typed, as the artist does
        dialog.accept();      // the Save button
        QVERIFY(dialog.isVisible());
        QCOMPARE(dialog.result(), int(QDialog::Rejected)); // not accepted
        auto* box = dialog.findChild<QMessageBox*>("fileNameProblem");
        QVERIFY(box);
        QVERIFY(QTest::qWaitFor([&] { return box->isVisible(); }, 5000));
        qInfo("%s -> \"%s\"", qPrintable(c.bad), qPrintable(box->text()));
        QVERIFY2(box->text().contains(c.says), qPrintable(box->text()));
        box->accept();
        QTRY_VERIFY(!dialog.findChild<QMessageBox*>("fileNameProblem"));
        name->setText(c.good);
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QVERIFY(!dialog.isVisible());
        QCOMPARE(dialog.selectedFiles().value(0), c.good);
        QVERIFY(dialog.lastProblem().isEmpty());
    }
}

void FilesSaveDialogTest::dialogAddsTheFiltersExtension() {
    QTemporaryDir dir;
    SaveFileDialog dialog(nullptr, SaveTarget::Render, dir.path());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    auto* name = dialog.findChild<QLineEdit*>("fileNameEdit");
    QVERIFY(name);
    name->setText("beauty");
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    QCOMPARE(dialog.selectedFiles().value(0), dir.filePath("beauty.exr"));
}

QTEST_MAIN(FilesSaveDialogTest)
#include "files_save_dialog_test.moc"
