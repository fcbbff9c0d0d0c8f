// PropertyCommand: one property edit on the undo stack. It holds the new and the previous value
// (changes(): the step as a scene::ChangeSet, whose inverse undo applies) and applies them
// through a callback (the document's commit, which hands the change set to the render thread),
// so commands know nothing of the document or the render thread. Edits of one gesture (same property, same non-zero GestureId: a
// slider drag, a spin-box scrub, a viewport drag) merge into one step; separate edits never do.
// The command's text names the step for the Edit menu ("sun intensity" -> "Undo sun intensity").
#pragma once

#include "commands/property_edit.h"

#include <QUndoCommand>

#include <functional>

namespace wavelit::editor {

class PropertyCommand : public QUndoCommand {
public:
    using Commit = std::function<void(const PropertyEdit&)>;
    static constexpr int kId = 0x5750; // "WP": QUndoStack merges only commands of one id

    // `text`: what the Edit menu calls the step; empty: "<kind> <property>".
    PropertyCommand(PropertyEdit edit, scene::PropertyValue previous, Commit commit,
                    const QString& text = {});

    void redo() override;
    void undo() override;
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand* other) override;

    const PropertyEdit& edit() const { return m_edit; }
    // The step as a change set (previous value -> value); undo applies changes().inverted().
    scene::ChangeSet changes() const;

private:
    PropertyEdit m_edit;
    scene::PropertyValue m_previous;
    Commit m_commit;
};

} // namespace wavelit::editor
