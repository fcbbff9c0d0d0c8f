// The file dialogs that name a file to write (File → Save scene as, Save lighting setup as, Render
// to file): the name is checked as the dialog closes, and a bad one — an extension the writer does
// not know, a folder that does not exist or cannot be written, a folder picked as the file — is
// reported in a message box over the dialog, which stays open for another name, instead of the
// write failing after the dialog (and, for Render to file, after the render). The dialog is Qt's
// own (not the platform's), whose accept() we can intercept; a name typed without an extension gets
// the selected filter's.
#pragma once

#include <QFileDialog>
#include <QStringList>

namespace wavelit::editor {

enum class SaveTarget { Scene, Lighting, Render };

// What is wrong with `path` as a file of one of `extensions` (lower case, without the dot) to
// write, or "" when nothing is. The folder is tested by creating (and removing) a temporary file
// in it, so a read-only mount or a pseudo file system is caught as well as permissions.
QString outputPathProblem(const QString& path, const QStringList& extensions);

class SaveFileDialog : public QFileDialog {
    Q_OBJECT
public:
    // objectName "saveFileDialog"; the message box it shows: "fileNameProblem".
    SaveFileDialog(QWidget* parent, SaveTarget target, const QString& startPath);
    const QStringList& extensions() const { return m_extensions; }
    // The problem shown for the last refused name ("" when the last accept() closed the dialog).
    const QString& lastProblem() const { return m_lastProblem; }

public slots:
    void accept() override;

private:
    QStringList m_extensions;
    QString m_lastProblem;
};

// Runs the dialog (modal) and returns the accepted path, "" when cancelled.
QString askSavePath(QWidget* parent, SaveTarget target, const QString& startPath);

} // namespace wavelit::editor
