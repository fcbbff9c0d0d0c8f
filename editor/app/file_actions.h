// FileActions (issue 14): the File menu's files beyond open/save (editor_actions.h) — New, Open
// recent, lighting setups (*.wllight: save the current one, apply one onto the open scene),
// environment maps and meshes brought in from files, Render to file, and drag-and-drop of
// .wlscene/.wllight/.exr/.hdr/.obj onto the window. Files are read and written on pool threads;
// each operation reports once through its `done` callback (empty = success). A failure also goes
// to the ErrorReporter — a dialog naming the file and the problem — and is kept as lastError()
// for scripts. Actions: actionNewScene, actionSaveLighting, actionApplyLighting, actionRenderToFile,
// actionClearRecent, and one actionRecent<N> per recent file.
#pragma once

#include "app/render_to_file.h"

#include <QObject>
#include <QString>

#include <functional>

class QMenu;
class QProgressDialog;

namespace wavelit::editor {

class MainWindow;
class RecentFiles;

class FileActions : public QObject {
    Q_OBJECT
public:
    using Done = std::function<void(const QString& error)>;

    explicit FileActions(MainWindow* window);

    // File -> New (asks "Save changes?" first when called from the menu).
    void newScene();
    // Writes the open document's lighting setup to `path` (*.wllight), its environment map path
    // re-expressed for that file's folder. The document is not changed.
    void saveLighting(const QString& path, Done done);
    // Loads `path` and puts it on the open scene as a reference (one undo step): environment and
    // lights replaced; Save writes the scene referring to it.
    void applyLighting(const QString& path, Done done);
    // The environment map becomes `path` (.exr/.hdr), checked by loading it first (one undo step).
    void setEnvironmentMap(const QString& path, Done done);
    // Loads a mesh (Assimp: .obj, .ply, .gltf, ...) and adds an object using it (one undo step).
    // The object's mesh path is stored relative to the scene file.
    void addObject(const QString& path, const QString& name, Done done);
    // What a drop of this file does: open (.wlscene), apply (.wllight), environment (.exr/.hdr),
    // add object (.obj); anything else is refused with a message.
    void openDropped(const QString& path, Done done);
    // Renders the current scene to `path` with the viewport's options; `progress` shows a dialog.
    void renderToFile(const QString& path, RenderBudget budget, bool showProgress, Done done);
    RenderToFile* fileRender() const { return m_render; }

    RecentFiles* recent() const { return m_recent; }
    // Drops whose file operation has not reported yet (scripts wait for 0).
    int pendingDrops() const { return m_pendingDrops; }
    QString lastError() const { return m_lastError; }
    int failures() const { return m_failures; } // how many operations failed so far

protected:
    bool eventFilter(QObject* watched, QEvent* event) override; // the window's drops

private:
    void rebuildRecentMenu();
    QString finish(const QString& title, const QString& error); // reports, records, returns it
    QString absoluteFromScene(const QString& path) const;

    MainWindow* m_window;
    RecentFiles* m_recent;
    RenderToFile* m_render;
    QMenu* m_recentMenu = nullptr;
    QProgressDialog* m_progress = nullptr;
    Done m_renderDone;
    QString m_lastError;
    int m_pendingDrops = 0;
    int m_failures = 0;
};

} // namespace wavelit::editor
