#include "app/editor_actions.h"

#include "app/save_file_dialog.h"
#include "app/scene_document.h"
#include "app/unsaved_changes_prompt.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenuBar>
#include <QUndoStack>

namespace wavelit::editor {
namespace {
const QString kSceneFilter = QObject::tr("Wavelit scenes (*.wlscene);;All files (*)");
} // namespace

EditorActions::EditorActions(QMainWindow* window, SceneDocument* document, ErrorReporter* errors)
    : QObject(window), m_window(window), m_document(document),
      m_prompt(new UnsavedChangesPrompt(window, document, errors, [this] { return save(); })) {
    QMenu* file = m_fileMenu = window->menuBar()->addMenu(tr("&File"));
    file->addAction(add("actionOpenScene", tr("&Open scene…"), QKeySequence::Open));
    file->addAction(add("actionSaveScene", tr("&Save scene"), QKeySequence::Save));
    file->addAction(add("actionSaveSceneAs", tr("Save scene &as…"), QKeySequence::SaveAs));
    file->addSeparator();
    file->addAction(add("actionQuit", tr("&Quit"), QKeySequence::Quit));

    QMenu* edit = m_editMenu = window->menuBar()->addMenu(tr("&Edit"));
    // The undo stack names each step: "Undo sun intensity".
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
    connect(action("actionSaveScene"), &QAction::triggered, this, [this] { save(); });
    connect(action("actionSaveSceneAs"), &QAction::triggered, this, [this] { saveAs(); });
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
    m_prompt->ask(tr("open another scene"), [this] {
        const QString dir = QFileInfo(m_document->path()).absolutePath();
        const QString path = QFileDialog::getOpenFileName(m_window, tr("Open scene"), dir, kSceneFilter);
        if (!path.isEmpty()) m_document->open(path);
    });
}

bool EditorActions::save() {
    if (!m_document->scene()) return false;
    if (m_document->path().isEmpty()) return saveAs();
    m_document->save();
    return true;
}

bool EditorActions::saveAs() {
    if (!m_document->scene()) return false;
    const QString path = askSavePath(m_window, SaveTarget::Scene, m_document->path()); // name checked there
    if (path.isEmpty()) return false;
    const auto choice = askLightingSave();
    if (!choice) return false;
    m_document->saveAs(path, *choice);
    return true;
}

std::optional<LightingSave> EditorActions::askLightingSave() {
    if (!m_document->lightingEdited()) return m_document->defaultLightingSave();
    const QString setup = QFileInfo(QString::fromStdString(m_document->scene()->lightingPath)).fileName();
    const QStringList items{
        tr("Save a copy of the edited setup beside the scene (%1 stays as it is)").arg(setup),
        tr("Write the lighting into the scene file"),
        tr("Save the edits into the shared setup %1").arg(setup),
    };
    bool ok = false;
    const QString picked = QInputDialog::getItem(m_window, tr("Lighting setup"),
                                                 tr("The lighting setup %1 was edited. Save it:").arg(setup),
                                                 items, 0, false, &ok);
    if (!ok) return std::nullopt;
    const LightingSave choices[] = {LightingSave::Copy, LightingSave::Inline, LightingSave::SaveSetup};
    return choices[std::max<qsizetype>(0, items.indexOf(picked))];
}

void EditorActions::changeExposure(float deltaEv) {
    auto scene = m_document->scene();
    if (!scene) return;
    // Out of the registry's range: the edit is refused and exposure stays where it is.
    (void)m_document->setExposure(scene->camera.exposureEv + deltaEv);
}

} // namespace wavelit::editor
