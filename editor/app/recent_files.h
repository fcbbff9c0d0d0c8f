// RecentFiles: the File -> Open recent list, newest first, at most kMax entries, kept in QSettings
// ("recentScenes"). WAVELIT_SETTINGS_DIR, when set, puts the settings in <dir>/wavelit.ini
// instead of the user's configuration (tests keep $HOME untouched).
#pragma once

#include <QObject>
#include <QStringList>

namespace wavelit::editor {

class RecentFiles : public QObject {
    Q_OBJECT
public:
    static constexpr int kMax = 8;

    explicit RecentFiles(QObject* parent = nullptr);
    QStringList files() const { return m_files; }
    void add(const QString& path); // moves it to the front; stored at once
    void clear();

signals:
    void changed(const QStringList& files);

private:
    void store();
    QStringList m_files;
};

} // namespace wavelit::editor
