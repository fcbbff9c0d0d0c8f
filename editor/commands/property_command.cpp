#include "commands/property_command.h"

namespace wavelit::editor {

PropertyCommand::PropertyCommand(PropertyEdit edit, scene::PropertyValue previous, Commit commit,
                                 const QString& text)
    : m_edit(std::move(edit)), m_previous(std::move(previous)), m_commit(std::move(commit)) {
    setText(!text.isEmpty() ? text
                            : QStringLiteral("%1 %2").arg(scene::entityKindName(m_edit.entity.kind),
                                                          QString::fromStdString(m_edit.name)));
}

scene::ChangeSet PropertyCommand::changes() const {
    scene::ChangeSet out;
    out.add(scene::PropertyEdit{m_edit.entity, m_edit.name, m_previous, m_edit.value});
    return out;
}

void PropertyCommand::redo() { m_commit(m_edit); }

void PropertyCommand::undo() { m_commit({m_edit.entity, m_edit.name, m_previous}); }

bool PropertyCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = static_cast<const PropertyCommand*>(other); // same id() => same class
    if (m_edit.gesture == kNoGesture || next->m_edit.gesture != m_edit.gesture) return false;
    if (next->m_edit.entity != m_edit.entity || next->m_edit.name != m_edit.name) return false;
    m_edit.value = next->m_edit.value; // keep our previous value: undo returns to before both
    return true;
}

} // namespace wavelit::editor
