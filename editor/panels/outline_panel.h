// OutlinePanel: the scene tree (Camera; Lighting -> Environment + lights; Objects; Materials).
// Rebuilt from a scene snapshot; the selection is reported as an EntityRef, so nothing else
// depends on tree items. Group rows ("Lighting", "Objects", "Materials") select nothing.
// LightMix: each light has a check box (checked: it emits; unchecked: muted); clicking it asks to
// mute or unmute the light, Alt-clicking it asks to solo it (docs/lightmix.md).
#pragma once

#include "panels/entity_ref.h"

#include <QStringList>
#include <QWidget>

#include <optional>

class QTreeWidget;
class QTreeWidgetItem;

namespace wavelit::editor {

class OutlinePanel : public QWidget {
    Q_OBJECT
public:
    explicit OutlinePanel(QWidget* parent = nullptr);

    void setScene(const scene::Scene& scene);
    void clear();
    std::optional<EntityRef> selectedEntity() const; // none for group rows / no selection
    bool select(EntityRef ref); // false if the entity is not in the tree

    // Display names of the entities listed under a group ("Lighting", "Objects", "Materials").
    QStringList namesUnder(const QString& group) const;
    QTreeWidget* tree() const { return m_tree; }

signals:
    void entitySelected(std::optional<wavelit::scene::EntityRef> ref);
    void muteRequested(wavelit::scene::EntityId light, bool muted);
    void soloRequested(wavelit::scene::EntityId light);

private:
    QTreeWidgetItem* findItem(EntityRef ref) const;

    QTreeWidget* m_tree;
};

} // namespace wavelit::editor
