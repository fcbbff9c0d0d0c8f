// EditorActions: the menu bar's actions and what they do. Every action has an objectName
// (actionOpenScene, actionSaveSceneAs, actionQuit, actionUndo, actionRedo, actionExposureUp,
// actionExposureDown, actionExposureReset) so scripts and tests trigger them by name, like MuseScore's dispatcher.
#pragma once

#include <QObject>

class QAction;
class QMainWindow;

namespace wavelit::editor {

class SceneDocument;

class EditorActions : public QObject {
    Q_OBJECT
public:
    static constexpr float kExposureStepEv = 0.5f;

    // Creates the actions and the File and View menus of `window`.
    EditorActions(QMainWindow* window, SceneDocument* document);

    QAction* action(const QString& objectName) const;

private:
    QAction* add(const QString& objectName, const QString& text, const QKeySequence& shortcut);
    void openScene();
    void saveSceneAs();
    void changeExposure(float deltaEv);

    QMainWindow* m_window;
    SceneDocument* m_document;
};

} // namespace wavelit::editor
