// MainWindow: assembles the docks (outline, properties), the viewport and the status bar, and
// wires signals between them, the document and the render controller. Behaviour lives in those
// parts (architecture.md §9: the window does no work of its own). The title carries the document's name
// and a modified marker; closing with unsaved changes asks first (app/unsaved_changes_prompt.h).
#pragma once

#include "viewport/render_controller.h"

#include <QMainWindow>

namespace wavelit::editor {

class AutosaveController;
class CameraOrbitHandler;
class EditorActions;
class FileActions;
class OutlineActions;
class ErrorReporter;
class OutlinePanel;
class PropertyPanel;
class LightMixPanel;
class LightMixCompare;
class RenderStatusLabel;
class SceneDocument;
class ViewportInteraction;
class ViewportWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(const RenderSettings& renderSettings, QWidget* parent = nullptr);
    ~MainWindow() override;

    SceneDocument* document() const { return m_document; }
    RenderController* renderer() const { return m_render; }
    ViewportWidget* viewport() const { return m_viewport; }
    OutlinePanel* outline() const { return m_outline; }
    PropertyPanel* properties() const { return m_properties; }
    LightMixPanel* lightMix() const { return m_lightMix; }
    LightMixCompare* lightMixCompare() const { return m_lightMixCompare; } // A/B (issue 21)
    ErrorReporter* errors() const { return m_errors; }
    EditorActions* actions() const { return m_actions; }
    CameraOrbitHandler* cameraHandler() const { return m_cameraHandler; }
    // Picking, gizmos (move/rotate), light shape handles, environment drag (viewport_interaction.h).
    ViewportInteraction* interaction() const { return m_interaction; }
    AutosaveController* autosave() const { return m_autosave; }
    // Files, outline and panels (issue 14): file_actions.h, outline_actions.h.
    FileActions* files() const { return m_files; }
    OutlineActions* outlineActions() const { return m_outlineActions; }
    RenderStatusLabel* statusLabel() const { return m_status; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void wireDocument();
    void updateTitle();
    void wireRendering();
    void wireViewportHandlers();
    void wireLightMix(); // LightMix (issue 21): the A/B view, Lighting → Extract sun
    void refreshProperties();

    SceneDocument* m_document;
    ErrorReporter* m_errors;
    RenderController* m_render;
    ViewportWidget* m_viewport;
    OutlinePanel* m_outline;
    PropertyPanel* m_properties;
    LightMixPanel* m_lightMix;
    LightMixCompare* m_lightMixCompare;
    RenderStatusLabel* m_status;
    EditorActions* m_actions;
    CameraOrbitHandler* m_cameraHandler;
    AutosaveController* m_autosave;
    ViewportInteraction* m_interaction = nullptr;
    FileActions* m_files = nullptr;
    OutlineActions* m_outlineActions = nullptr;
    bool m_closeApproved = false;
};

} // namespace wavelit::editor
