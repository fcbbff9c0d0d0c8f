// OutlineActions (issue 14): add, delete, duplicate and rename entities from the Edit menu's Add
// submenu, the outline's context menu and scripts; each is one undo step (app/outline_edits.h
// builds the change set, SceneDocument::applyChanges records it). The added or duplicated entity
// is selected. Actions: actionAddPointLight, actionAddSphereLight, actionAddRectLight,
// actionAddSpotLight, actionAddSunLight, actionAddObject (a file dialog), actionAddMaterial,
// actionDelete (Del), actionDuplicate (Ctrl+D), actionRename (F2).
#pragma once

#include "panels/entity_ref.h"

#include "scene/change_set.h"
#include "util/result.h"

#include <QObject>
#include <QString>

#include <optional>

namespace wavelit::editor {

class MainWindow;

class OutlineActions : public QObject {
    Q_OBJECT
public:
    explicit OutlineActions(MainWindow* window);

    // Each returns the entity it made (or nothing for a removal) or an error with a message.
    util::Result<EntityRef> addLight(const QString& type, const QString& name);
    util::Result<EntityRef> addMaterial(const QString& name);
    util::Result<EntityRef> duplicate(EntityRef ref);
    util::Status remove(EntityRef ref);
    util::Status rename(EntityRef ref, const QString& name);

private:
    util::Result<EntityRef> push(util::Result<scene::ChangeSet> changes, const QString& text);
    void report(const QString& title, const util::Status& status);

    MainWindow* m_window;
};

} // namespace wavelit::editor
