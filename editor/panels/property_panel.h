// PropertyPanel: the properties of the selected entity, one row per registry property (label and
// an editor widget chosen by type, panels/property_editors.h). The panel never edits the scene:
// it emits editRequested and the document checks, applies and records it for undo. When the same
// entity is shown again (after an edit or an undo) the editors are refreshed in place, so the
// widget that sent an edit is never destroyed while it is still emitting.
#pragma once

#include "commands/property_edit.h"
#include "panels/entity_ref.h"
#include "panels/property_editors.h"

#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

class QLabel;
class QTableWidget;

namespace wavelit::editor {

class PropertyPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertyPanel(QWidget* parent = nullptr);

    // Shows `ref`'s properties in `scene`, or an empty panel for nullopt.
    void showEntity(const scene::Scene& scene, std::optional<EntityRef> ref);
    void clear();

    QTableWidget* table() const { return m_table; }
    QString title() const;
    // The editor widget of a property of the shown entity (objectName "edit_<name>"), or null.
    QWidget* editorFor(const QString& propertyName) const;
    // The line under the table that says why a typed value was refused ("" when none).
    QString message() const;
    void showMessage(const QString& text);
    // The folder a picked file's path is made relative to, per entity kind (file_actions.cpp sets
    // it: the scene's folder, or the lighting setup's for the environment map).
    void setFolderFor(std::function<QString(scene::EntityKind)> folder) { m_folderFor = std::move(folder); }

signals:
    void editRequested(const wavelit::editor::PropertyEdit& edit);
    void valueRefused(const QString& message);

private:
    void rebuild(const scene::Scene& scene, EntityRef ref);

    QLabel* m_title;
    QTableWidget* m_table;
    QLabel* m_message;
    std::function<QString(scene::EntityKind)> m_folderFor;
    std::optional<EntityRef> m_shown;
    std::vector<const scene::PropertyInfo*> m_infos; // the rows, in order
    std::vector<PropertyEditor> m_editors;
};

} // namespace wavelit::editor
