#include "app/editor_actions.h"

#include "app/scene_document.h"

#include <QAction>
#include <QUndoStack>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenuBar>

namespace wavelit::editor {
namespace {
const QString kSceneFilter = QObject::tr("Wavelit scenes (*.wlscene);;All files (*)");
} // namespace

EditorActions::EditorActions(QMainWindow* window, SceneDocument* document)
    : QObject(window), m_window(window), m_document(document) {
    QMenu* file = window->menuBar()->addMenu(tr("&File"));
    file->addAction(add("actionOpenScene", tr("&Open scene…"), QKeySequence::Open));
    file->addAction(add("actionSaveSceneAs", tr("Save scene &as…"), QKeySequence::SaveAs));
    file->addSeparator();
    file->addAction(add("actionQuit", tr("&Quit"), QKeySequence::Quit));

    QMenu* edit = window->menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document->undoStack()->createUndoAction(window, tr("&Undo"));
    undo->setObjectName("actionUndo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = document->undoStack()->createRedoAction(window, tr("&Redo"));
    redo->setObjectName("actionRedo");
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu* view = window->menuBar()->addMenu(tr("&View"));
    view->addAction(add("actionExposureUp", tr("Exposure &up"), QKeySequence(Qt::Key_Plus)));
    view->addAction(add("actionExposureDown", tr("Exposure &down"), QKeySequence(Qt::Key_Minus)));
    view->addAction(add("actionExposureReset", tr("&Reset exposure"), QKeySequence(Qt::Key_0)));

    connect(action("actionOpenScene"), &QAction::triggered, this, &EditorActions::openScene);
    connect(action("actionSaveSceneAs"), &QAction::triggered, this, &EditorActions::saveSceneAs);
    connect(action("actionQuit"), &QAction::triggered, window, &QMainWindow::close);
    connect(action("actionExposureUp"), &QAction::triggered, this,
            [this] { changeExposure(kExposureStepEv); });
    connect(action("actionExposureDown"), &QAction::triggered, this,
            [this] { changeExposure(-kExposureStepEv); });
    connect(action("actionExposureReset"), &QAction::triggered, this, [this] {
        if (auto scene = m_document->scene()) changeExposure(-scene->camera.exposureEv);
    });
}

QAction* EditorActions::action(const QString& objectName) const {
    return m_window->findChild<QAction*>(objectName);
}

QAction* EditorActions::add(const QString& objectName, const QString& text,
                            const QKeySequence& shortcut) {
    auto* a = new QAction(text, m_window);
    a->setObjectName(objectName);
    a->setShortcut(shortcut);
    m_window->addAction(a);
    return a;
}

void EditorActions::openScene() {
    const QString dir = QFileInfo(m_document->path()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Open scene"), dir, kSceneFilter);
    if (!path.isEmpty()) m_document->open(path);
}

void EditorActions::saveSceneAs() {
    const QString path =
        QFileDialog::getSaveFileName(m_window, tr("Save scene as"), m_document->path(), kSceneFilter);
    if (!path.isEmpty()) m_document->saveAs(path);
}

void EditorActions::changeExposure(float deltaEv) {
    auto scene = m_document->scene();
    if (!scene) return;
    // Out of the registry's range: the edit is refused and exposure stays where it is.
    (void)m_document->setExposure(scene->camera.exposureEv + deltaEv);
}

} // namespace wavelit::editor
