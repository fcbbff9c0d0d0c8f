// EditorActions: the menu bar's actions and what they do. Every action has an objectName
// (actionOpenScene, actionSaveScene, actionSaveSceneAs, actionQuit, actionUndo, actionRedo,
// actionExposureUp, actionExposureDown, actionExposureReset) so scripts and tests trigger them by
// name, like MuseScore's dispatcher. Opening another scene asks "Save changes?" first
// (app/unsaved_changes_prompt.h); Quit closes the window, which asks too.
#pragma once

#include "app/save_plan.h"

#include <QObject>

#include <optional>

class QAction;
class QMainWindow;
class QMenu;

namespace wavelit::editor {

class ErrorReporter;
class SceneDocument;
class UnsavedChangesPrompt;

class EditorActions : public QObject {
    Q_OBJECT
public:
    static constexpr float kExposureStepEv = 0.5f;

    // Creates the actions and the File, Edit and View menus of `window`.
    EditorActions(QMainWindow* window, SceneDocument* document, ErrorReporter* errors);

    QAction* action(const QString& objectName) const;
    UnsavedChangesPrompt* prompt() const { return m_prompt; }
    // The menus, for the parts that add their own actions (file_actions.h, outline_actions.h).
    QMenu* fileMenu() const { return m_fileMenu; }
    QMenu* editMenu() const { return m_editMenu; }

    // Save: to the document's file, or through Save As when it has none. False when no save
    // started (the user cancelled a dialog).
    bool save();
    // Save As: a file dialog, then — for edited referenced lighting — where the lighting goes.
    bool saveAs();

private:
    QAction* add(const QString& objectName, const QString& text, const QKeySequence& shortcut);
    void openScene();
    std::optional<LightingSave> askLightingSave(); // nullopt: cancelled
    void changeExposure(float deltaEv);

    QMainWindow* m_window;
    SceneDocument* m_document;
    UnsavedChangesPrompt* m_prompt;
    QMenu* m_fileMenu = nullptr;
    QMenu* m_editMenu = nullptr;
};

} // namespace wavelit::editor
