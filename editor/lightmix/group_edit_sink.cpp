#include "lightmix/group_edit_sink.h"

#include "app/scene_document.h"

#include <QUndoStack>

namespace wavelit::editor {

GroupEditSink::GroupEditSink(SceneDocument* document, std::function<void(const QString&)> report, QObject* parent)
    : QObject(parent), m_document(document), m_report(std::move(report)) {}

GroupEditSink::~GroupEditSink() { endGesture(); }

void GroupEditSink::apply(const scene::ChangeSet& changes, const QString& text, GestureId gesture) {
    if (!m_document) return;
    if (gesture != m_macroGesture) endGesture();
    if (gesture != kNoGesture && m_macroGesture == kNoGesture) {
        m_document->undoStack()->beginMacro(text);
        m_macroGesture = gesture;
    }
    if (auto status = m_document->applyChanges(changes, text); !status && m_report)
        m_report(QString::fromStdString(status.error().message()));
}

void GroupEditSink::endGesture() {
    if (m_macroGesture == kNoGesture) return;
    m_macroGesture = kNoGesture;
    if (m_document) m_document->undoStack()->endMacro();
}

} // namespace wavelit::editor
