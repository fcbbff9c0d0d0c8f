#include "panels/render_status_label.h"

namespace wavelit::editor {

RenderStatusLabel::RenderStatusLabel(QWidget* parent) : QLabel(parent) {
    setObjectName("renderStatus");
    setText(tr("idle"));
}

QString RenderStatusLabel::format(const RenderFrame& frame) {
    QString text = tr("%1 spp · %2 s").arg(frame.samplesPerPixel).arg(frame.elapsedSeconds, 0, 'f', 1);
    if (!frame.deviceName.isEmpty()) text += QStringLiteral(" · ") + frame.deviceName;
    // What the last edit cost (architecture.md §5.B): a light drag should read "uploaded: lights".
    if (!frame.lastUpdate.isEmpty()) text += QStringLiteral(" — ") + frame.lastUpdate;
    return text;
}

void RenderStatusLabel::showFrame(const RenderFrame& frame) { setText(format(frame)); }

void RenderStatusLabel::showState(const QString& text) { setText(text); }

} // namespace wavelit::editor
