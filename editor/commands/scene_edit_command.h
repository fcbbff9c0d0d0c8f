// SceneEditCommand: an outline edit on the undo stack — entities added, removed or duplicated, as
// one scene::ChangeSet (change_set.h: each add/remove carries the entity's full state and its
// position in its list, so the inverse puts a deleted light back where it was). Redo applies the
// set, undo its inverse, both through a callback (the document's commitChanges, which hands the
// set to the render thread), so the command knows nothing of the document. Never merges.
#pragma once

#include "scene/change_set.h"

#include <QUndoCommand>

#include <functional>

namespace wavelit::editor {

class SceneEditCommand : public QUndoCommand {
public:
    using Commit = std::function<void(const scene::ChangeSet&)>;

    // `text`: the Edit menu's name of the step ("add light Key", "delete object ring").
    SceneEditCommand(scene::ChangeSet changes, Commit commit, const QString& text);

    void redo() override { m_commit(m_changes); }
    void undo() override { m_commit(m_changes.inverted()); }

    const scene::ChangeSet& changes() const { return m_changes; }

private:
    scene::ChangeSet m_changes;
    Commit m_commit;
};

} // namespace wavelit::editor
