#include "app/main_window.h"

#include "app/autosave_controller.h"
#include "app/editor_actions.h"
#include "app/error_reporter.h"
#include "app/extract_sun_edit.h"
#include "app/file_actions.h"
#include "app/lightmix_compare.h"
#include "lightmix/group_edit_sink.h"
#include "app/outline_actions.h"
#include "app/scene_document.h"
#include "app/unsaved_changes_prompt.h"
#include "panels/outline_panel.h"
#include "panels/lightmix_panel.h"
#include "panels/property_panel.h"
#include "panels/render_status_label.h"
#include "viewport/camera_orbit_handler.h"
#include "viewport/viewport_edit_sink.h"
#include "viewport/viewport_interaction.h"
#include "viewport/viewport_widget.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTreeWidget>

#include <initializer_list>

namespace wavelit::editor {
namespace {

QDockWidget* addDock(QMainWindow* window, const QString& title, const QString& name,
                     QWidget* content, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, window);
    dock->setObjectName(name);
    dock->setWidget(content);
    window->addDockWidget(area, dock);
    return dock;
}

} // namespace

MainWindow::MainWindow(const RenderSettings& renderSettings, QWidget* parent)
    : QMainWindow(parent), m_document(new SceneDocument(this)), m_errors(new ErrorReporter(this)),
      m_render(new RenderController(renderSettings, this)), m_viewport(new ViewportWidget(this)),
      m_outline(new OutlinePanel(this)), m_properties(new PropertyPanel(this)),
      m_lightMix(new LightMixPanel(this)), m_lightMixCompare(nullptr),
      m_status(new RenderStatusLabel(this)), m_actions(new EditorActions(this, m_document, m_errors)),
      m_cameraHandler(new CameraOrbitHandler(this)),
      m_autosave(new AutosaveController(m_document, m_errors, this)) {
    setObjectName("mainWindow");
    updateTitle();
    setCentralWidget(m_viewport);
    addDock(this, tr("Scene"), "outlineDock", m_outline, Qt::LeftDockWidgetArea);
    addDock(this, tr("Properties"), "propertyDock", m_properties, Qt::RightDockWidgetArea);
    addDock(this, tr("LightMix"), "lightMixDock", m_lightMix, Qt::RightDockWidgetArea);
    statusBar()->addPermanentWidget(m_status);
    resize(1100, 700);
    wireDocument();
    wireRendering();
    wireViewportHandlers();
    m_files = new FileActions(this);            // New, recent, lighting setups, render to file, drops
    m_outlineActions = new OutlineActions(this); // add, delete, duplicate, rename
    m_status->setSampler(render::samplerKindName(renderSettings.sampler));
    wireLightMix();
}

// Declared here so the render controller (a child) is destroyed, and its thread joined, while
// the widgets it signals still exist. First the panels and the document go quiet: ~QWidget
// closes the window and moves the focus while it deletes the children one by one, so a text
// field still holding edited text commits it (editingFinished) — and that edit, applied to the
// document, rebuilt panels already deleted (LightMixPanel::rebuild crashed on its layout).
// Nothing the window shows may change once it is going.
MainWindow::~MainWindow() {
    for (QObject* source : std::initializer_list<QObject*>{m_properties, m_lightMix, m_outline, m_document})
        source->blockSignals(true);
    delete m_render;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (m_closeApproved || !m_document->isModified()) {
        m_render->shutdown(); // stops a running pass within a piece (~40 ms) and joins
        if (m_closeApproved) m_autosave->discardRecovery(); // saved or discarded on purpose
        event->accept();
        return;
    }
    event->ignore();
    m_actions->prompt()->ask(tr("close"), [this] {
        m_closeApproved = true;
        // Queued: this may run inside the close event being refused right now.
        QMetaObject::invokeMethod(this, &QWidget::close, Qt::QueuedConnection);
    });
}

void MainWindow::updateTitle() {
    const QString path = m_document->path();
    setWindowTitle(path.isEmpty() ? tr("Wavelit[*]") : tr("%1[*] — Wavelit").arg(QFileInfo(path).fileName()));
    setWindowModified(m_document->isModified());
}

void MainWindow::wireDocument() {
    connect(m_document, &SceneDocument::sceneOpened, this,
            [this](std::shared_ptr<const scene::Scene> scene, const QString& path) {
                updateTitle();
                m_outline->setScene(*scene);
                refreshProperties();
                m_viewport->clear();
                m_viewport->setExposure(scene->camera.exposureEv);
                m_status->showState(tr("starting renderer…"));
                m_render->render(std::move(scene), path);
            });
    connect(m_document, &SceneDocument::sceneEdited, this,
            [this](std::shared_ptr<const scene::Scene> scene, const scene::ChangeSet& changes) {
                m_outline->setScene(*scene);
                refreshProperties();
                m_render->renderEdit(std::move(scene), m_document->path(), changes);
            });
    connect(m_document, &SceneDocument::displayChanged, this,
            [this](std::shared_ptr<const scene::Scene> scene) {
                m_viewport->setExposure(scene->camera.exposureEv);
                m_outline->setScene(*scene); // names are display edits too
                refreshProperties();
            });
    connect(m_document, &SceneDocument::openFailed, this,
            [this](const QString& message) { m_errors->report(tr("Open scene"), message); });
    connect(m_document, &SceneDocument::saveFailed, this,
            [this](const QString& message) { m_errors->report(tr("Save scene"), message); });
    connect(m_document, &SceneDocument::editFailed, this,
            [this](const QString& message) { m_errors->report(tr("Edit"), message); });
    connect(m_document, &SceneDocument::saved, this, [this](const QString& path) {
        statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
        updateTitle();
    });
    connect(m_document, &SceneDocument::modifiedChanged, this, [this] { updateTitle(); });
    connect(m_document, &SceneDocument::openRepaired, this,
            [this](const QString& message) { m_errors->warn(tr("Open scene"), message); });
    connect(m_outline, &OutlinePanel::entitySelected, this, [this] { refreshProperties(); });
    auto applyEdit = [this](const PropertyEdit& edit) {
        if (auto status = m_document->apply(edit); !status) {
            m_errors->report(tr("Edit"), QString::fromStdString(status.error().message()));
            refreshProperties(); // show the value that is still in effect
        }
    };
    connect(m_properties, &PropertyPanel::editRequested, this, applyEdit);
    connect(m_lightMix, &LightMixPanel::editRequested, this, applyEdit);
    auto* groupEdits = new GroupEditSink( // LightMix group rows: one change set, one undo step
        m_document, [this](const QString& message) { m_errors->report(tr("LightMix"), message); }, this);
    connect(m_lightMix, &LightMixPanel::groupEditRequested, groupEdits, &GroupEditSink::apply);
    connect(m_lightMix, &LightMixPanel::groupGestureEnded, groupEdits, &GroupEditSink::endGesture);
    connect(m_outline, &OutlinePanel::muteRequested, this, [applyEdit](scene::EntityId id, bool muted) {
        applyEdit({{EntityKind::Light, id}, "muted", muted});
    });
    connect(m_outline, &OutlinePanel::soloRequested, this, [this](scene::EntityId id) {
        if (auto status = m_document->solo(id); !status)
            m_errors->report(tr("Solo"), QString::fromStdString(status.error().message()));
    });
}

void MainWindow::wireRendering() {
    connect(m_viewport, &ViewportWidget::exposureChanged, m_render, &RenderController::setExposure);
    // The viewport shows the newest honest image: the preview or the path tracer (render_controller.h).
    connect(m_render, &RenderController::displayFrame, this, [this](const RenderFrame& frame) {
        m_viewport->showFrame(frame);
        m_status->showFrame(frame);
    });
    connect(m_render, &RenderController::failed, this, [this](const QString& message) {
        m_autosave->autosaveNow(); // a failing renderer may be a dying process: keep the edits
        m_status->showState(tr("render failed"));
        m_errors->report(tr("Render"), message);
    });
}

void MainWindow::wireViewportHandlers() {
    m_viewport->installEventFilter(m_cameraHandler);
    auto follow = [this](std::shared_ptr<const scene::Scene> scene) {
        m_cameraHandler->setCamera(scene->camera);
    };
    connect(m_document, &SceneDocument::sceneOpened, m_cameraHandler, follow);
    connect(m_document, &SceneDocument::sceneEdited, m_cameraHandler, follow);
    connect(m_cameraHandler, &CameraOrbitHandler::cameraMoved, this,
            [this](const glm::vec3& p, GestureId gesture) {
        const EntityRef camera{EntityKind::Camera, scene::kInvalidId};
        if (auto status = m_document->apply({camera, "position", p, gesture}); !status)
            m_errors->report(tr("Camera"), QString::fromStdString(status.error().message()));
    });
    // Viewport (issue 14): picking, gizmos, environment drag, pan and frame (viewport_interaction.h).
    auto* interaction = new ViewportInteraction(m_viewport, this); // filters before the camera
    m_interaction = interaction;
    interaction->setObjectName("viewportInteraction");
    // A manipulator drag held at its range's limit says so in the status bar too (the viewport
    // draws it beside the light).
    connect(interaction, &ViewportInteraction::clampNotice, this, [this](const QString& message) {
        if (!message.isEmpty()) statusBar()->showMessage(message, 5000);
    });
    m_viewport->installEventFilter(interaction);
    auto* sink = new ViewportEditSink(
        m_document->undoStack(), [this](const PropertyEdit& edit) { return m_document->apply(edit); },
        [this](const QString& message) { m_errors->report(tr("Viewport"), message); }, this);
    auto track = [interaction](std::shared_ptr<const scene::Scene> scene) { interaction->setScene(scene); };
    connect(m_document, &SceneDocument::sceneOpened, interaction, track);
    connect(m_document, &SceneDocument::sceneEdited, interaction, track);
    connect(m_document, &SceneDocument::displayChanged, interaction, track);
    connect(m_outline, &OutlinePanel::entitySelected, interaction, &ViewportInteraction::setSelection);
    connect(m_outline, &OutlinePanel::entitySelected, m_render, &RenderController::selectionChanged);
    connect(interaction, &ViewportInteraction::selectRequested, this, [this](std::optional<EntityRef> ref) {
        if (!ref || !m_outline->select(*ref)) m_outline->tree()->clearSelection();
    });
    connect(interaction, &ViewportInteraction::editRequested, sink, &ViewportEditSink::applyEdit);
    connect(m_cameraHandler, &CameraOrbitHandler::viewMoved, sink, &ViewportEditSink::applyView);
    connect(interaction, &ViewportInteraction::viewRequested, sink,
            [sink](const glm::vec3& p, const glm::vec3& t) { sink->applyView(p, t, kNoGesture); });
    connect(interaction, &ViewportInteraction::dragActiveChanged, sink, [this, sink](bool active) {
        m_render->setInteractive(active); // drafts while the drag lasts (render_worker.h)
        if (!active) sink->endGesture();
    });
}

void MainWindow::refreshProperties() {
    if (auto scene = m_document->scene()) {
        m_properties->showEntity(*scene, m_outline->selectedEntity());
        m_lightMix->setScene(*scene);
    } else
        m_properties->clear();
}

// LightMix (issue 21): the A/B split view over the viewport follows every frame, and
// Lighting → Extract sun turns the environment's sun into a light (one undo step).
void MainWindow::wireLightMix() {
    m_lightMixCompare = new LightMixCompare(m_viewport);
    connect(m_render, &RenderController::frameReady, this, [this](const RenderFrame& frame) {
        if (auto shown = m_lightMixCompare->showFrame(frame); !shown)
            statusBar()->showMessage(QString::fromStdString(shown.error().message()), 5000);
    });
    connect(m_lightMixCompare, &LightMixCompare::sideRenderFailed, this,
            [this](const QString& message) { m_errors->report(tr("A/B compare"), message); });
    QMenu* lighting = menuBar()->addMenu(tr("&Lighting"));
    QAction* extract = lighting->addAction(tr("Extract sun"));
    extract->setObjectName("actionExtractSun");
    connect(extract, &QAction::triggered, this, [this] {
        auto name = extractSunEdit(*m_document);
        if (!name) m_errors->report(tr("Extract sun"), QString::fromStdString(name.error().message()));
    });
    QAction* endCompare = lighting->addAction(tr("End A/B compare"));
    endCompare->setObjectName("actionEndCompare");
    connect(endCompare, &QAction::triggered, m_lightMixCompare, &LightMixCompare::stop);
}

} // namespace wavelit::editor
