#include "viewport/viewport_edit_sink.h"

#include <QUndoStack>

namespace wavelit::editor {

ViewportEditSink::ViewportEditSink(QUndoStack* stack, Apply apply, Report report, QObject* parent)
    : QObject(parent), m_stack(stack), m_apply(std::move(apply)), m_report(std::move(report)) {}

void ViewportEditSink::apply(const PropertyEdit& edit) {
    if (auto status = m_apply(edit); !status) m_report(QString::fromStdString(status.error().message()));
}

void ViewportEditSink::applyEdit(const PropertyEdit& edit) {
    if (m_macroOpen && edit.gesture != m_macroGesture) endGesture();
    apply(edit);
}

void ViewportEditSink::applyView(const glm::vec3& position, const glm::vec3& target, GestureId gesture) {
    const EntityRef camera{EntityKind::Camera, scene::kInvalidId};
    if (m_macroOpen && (gesture != m_macroGesture || gesture == kNoGesture)) endGesture();
    if (!m_macroOpen) {
        m_stack->beginMacro(tr("camera view"));
        m_macroOpen = true;
        m_macroGesture = gesture;
    }
    apply({camera, "position", position, gesture});
    apply({camera, "target", target, gesture});
    if (gesture == kNoGesture) endGesture();
}

void ViewportEditSink::endGesture() {
    if (!m_macroOpen) return;
    m_stack->endMacro();
    m_macroOpen = false;
    m_macroGesture = kNoGesture;
}

} // namespace wavelit::editor
