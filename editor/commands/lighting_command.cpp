#include "commands/lighting_command.h"

namespace wavelit::editor {

LightingCommand::LightingCommand(LightingState before, LightingState after, Commit commit,
                                 const QString& text)
    : m_before(std::move(before)), m_after(std::move(after)), m_commit(std::move(commit)) {
    setText(text);
}

} // namespace wavelit::editor
