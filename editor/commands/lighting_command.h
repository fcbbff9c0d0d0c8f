// LightingCommand: "apply lighting setup" on the undo stack. A setup replaces the whole lighting
// of a scene (environment and every light) and where it lives (inline, or a *.wllight the scene
// refers to), which no property edit expresses; the command holds both states and swaps them
// through a callback (the document's commitLighting). Never merges.
#pragma once

#include "scene/scene.h"

#include <QUndoCommand>

#include <functional>
#include <string>

namespace wavelit::editor {

// What a lighting swap replaces: the setup, the file the scene refers to for it ("" = inline),
// and the setup as that file holds it (what "lighting edited?" compares against).
struct LightingState {
    scene::LightingSetup lighting;
    std::string lightingPath;
    scene::LightingSetup savedLighting;
};

class LightingCommand : public QUndoCommand {
public:
    using Commit = std::function<void(const LightingState&)>;

    LightingCommand(LightingState before, LightingState after, Commit commit, const QString& text);

    void redo() override { m_commit(m_after); }
    void undo() override { m_commit(m_before); }

private:
    LightingState m_before;
    LightingState m_after;
    Commit m_commit;
};

} // namespace wavelit::editor
