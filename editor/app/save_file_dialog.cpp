#include "app/save_file_dialog.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QTemporaryFile>

namespace wavelit::editor {
namespace {

struct TargetInfo {
    QString title;
    QString filter;
    QStringList extensions;
};

TargetInfo targetInfo(SaveTarget target) {
    switch (target) {
    case SaveTarget::Scene: return {QObject::tr("Save scene as"), QObject::tr("Wavelit scenes (*.wlscene)"), {"wlscene"}};
    case SaveTarget::Lighting:
        return {QObject::tr("Save lighting setup"), QObject::tr("Lighting setups (*.wllight)"), {"wllight"}};
    case SaveTarget::Render:
        return {QObject::tr("Render to file"), QObject::tr("OpenEXR (*.exr);;PNG (*.png)"), {"exr", "png"}};
    }
    return {};
}

} // namespace

QString outputPathProblem(const QString& path, const QStringList& extensions) {
    if (path.trimmed().isEmpty()) return QObject::tr("No file name was given.");
    const QFileInfo info(path);
    if (info.isDir()) return QObject::tr("%1 is a folder, not a file name.").arg(path);
    const QString suffix = info.suffix().toLower();
    if (!extensions.contains(suffix)) {
        QStringList dotted;
        for (const QString& e : extensions) dotted << "." + e;
        return QObject::tr("%1: the extension must be %2%3.")
            .arg(info.fileName(), dotted.join(QObject::tr(" or ")),
                 suffix.isEmpty() ? QString() : QObject::tr(", not .%1").arg(suffix));
    }
    const QDir folder = info.absoluteDir();
    if (!folder.exists()) return QObject::tr("The folder %1 does not exist.").arg(folder.path());
    if (info.exists() && !info.isWritable()) return QObject::tr("%1 exists and cannot be overwritten.").arg(path);
    QTemporaryFile probe(folder.filePath(".wavelit-write-test-XXXXXX"));
    if (!probe.open()) return QObject::tr("The folder %1 cannot be written to: %2").arg(folder.path(), probe.errorString());
    return {};
}

SaveFileDialog::SaveFileDialog(QWidget* parent, SaveTarget target, const QString& startPath)
    : QFileDialog(parent) {
    const TargetInfo t = targetInfo(target);
    setObjectName("saveFileDialog");
    setWindowTitle(t.title);
    setOption(QFileDialog::DontUseNativeDialog); // the platform's dialog would close without asking us
    setAcceptMode(QFileDialog::AcceptSave);
    setFileMode(QFileDialog::AnyFile);
    setNameFilter(t.filter);
    setDefaultSuffix(t.extensions.front());
    m_extensions = t.extensions;
    const QFileInfo start(startPath);
    if (!startPath.isEmpty()) {
        setDirectory(start.isDir() ? startPath : start.absolutePath());
        if (!start.isDir()) selectFile(start.fileName());
    }
    // A name typed without an extension gets the selected filter's (".png" when PNG is chosen).
    connect(this, &QFileDialog::filterSelected, this, [this](const QString& filter) {
        for (const QString& e : m_extensions)
            if (filter.contains("*." + e)) setDefaultSuffix(e);
    });
}

void SaveFileDialog::accept() {
    const QStringList files = selectedFiles();
    const QString path = files.isEmpty() ? QString() : files.front();
    m_lastProblem = outputPathProblem(path, m_extensions);
    if (m_lastProblem.isEmpty()) {
        QFileDialog::accept();
        return;
    }
    // Over the dialog, which stays open for another name.
    auto* box = new QMessageBox(QMessageBox::Warning, windowTitle(), m_lastProblem, QMessageBox::Ok, this);
    box->setObjectName("fileNameProblem");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

QString askSavePath(QWidget* parent, SaveTarget target, const QString& startPath) {
    SaveFileDialog dialog(parent, target, startPath);
    if (dialog.exec() != QDialog::Accepted) return {};
    const QStringList files = dialog.selectedFiles();
    return files.isEmpty() ? QString() : files.front();
}

} // namespace wavelit::editor
