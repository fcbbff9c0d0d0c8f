#include "commands/scene_edit_command.h"

namespace wavelit::editor {

SceneEditCommand::SceneEditCommand(scene::ChangeSet changes, Commit commit, const QString& text)
    : m_changes(std::move(changes)), m_commit(std::move(commit)) {
    setText(text);
}

} // namespace wavelit::editor
