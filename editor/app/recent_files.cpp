#include "app/recent_files.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

#include <memory>

namespace wavelit::editor {
namespace {

constexpr const char* kKey = "recentScenes";

std::unique_ptr<QSettings> openSettings() {
    const QString dir = qEnvironmentVariable("WAVELIT_SETTINGS_DIR");
    if (!dir.isEmpty()) {
        QDir().mkpath(dir);
        return std::make_unique<QSettings>(dir + "/wavelit.ini", QSettings::IniFormat);
    }
    return std::make_unique<QSettings>();
}

} // namespace

RecentFiles::RecentFiles(QObject* parent) : QObject(parent) {
    m_files = openSettings()->value(kKey).toStringList();
}

void RecentFiles::add(const QString& path) {
    if (path.isEmpty()) return;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_files.removeAll(absolute);
    m_files.prepend(absolute);
    while (m_files.size() > kMax) m_files.removeLast();
    store();
}

void RecentFiles::clear() {
    m_files.clear();
    store();
}

void RecentFiles::store() {
    auto settings = openSettings();
    settings->setValue(kKey, m_files);
    settings->sync();
    emit changed(m_files);
}

} // namespace wavelit::editor
