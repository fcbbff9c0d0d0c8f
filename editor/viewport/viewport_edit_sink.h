// ViewportEditSink: turns the viewport handlers' requests into document edits. Single-property
// drags (a gizmo move, a sun turn, the environment's rotation, an orbit) carry a GestureId and
// merge into one undo step by themselves (commands/property_command.h). A camera view change
// sets two properties (position and target: a pan, "frame selected"); their edits alternate, so
// they cannot merge: the sink groups each view gesture into one undo macro ("Camera view"),
// closed when the drag ends (endGesture) — one drag, one undo step.
#pragma once

#include "commands/property_edit.h"

#include "util/result.h"

#include <QObject>

#include <functional>

class QUndoStack;

namespace wavelit::editor {

class ViewportEditSink : public QObject {
    Q_OBJECT
public:
    using Apply = std::function<util::Status(const PropertyEdit&)>;
    using Report = std::function<void(const QString& message)>;
    ViewportEditSink(QUndoStack* stack, Apply apply, Report report, QObject* parent = nullptr);

    void applyEdit(const PropertyEdit& edit);
    // kNoGesture: one macro of its own (frame selected).
    void applyView(const glm::vec3& position, const glm::vec3& target, GestureId gesture);
    void endGesture();

private:
    void apply(const PropertyEdit& edit);
    QUndoStack* m_stack;
    Apply m_apply;
    Report m_report;
    GestureId m_macroGesture = kNoGesture;
    bool m_macroOpen = false;
};

} // namespace wavelit::editor
