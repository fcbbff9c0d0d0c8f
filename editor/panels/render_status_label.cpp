#include "panels/render_status_label.h"

namespace wavelit::editor {

RenderStatusLabel::RenderStatusLabel(QWidget* parent) : QLabel(parent) {
    setObjectName("renderStatus");
    setText(tr("idle"));
}

QString RenderStatusLabel::format(const RenderFrame& frame, const QString& sampler, std::optional<double> noise) {
    QString text = tr("%1 spp · %2 s").arg(frame.samplesPerPixel).arg(frame.elapsedSeconds, 0, 'f', 1);
    if (frame.image && frame.elapsedSeconds > 0.0) {
        const double samples = double(frame.samplesPerPixel) * frame.image->width * frame.image->height;
        text += tr(" · %1 Msamples/s").arg(samples / frame.elapsedSeconds * 1e-6, 0, 'f', 2);
    }
    if (!sampler.isEmpty()) text += QStringLiteral(" · ") + sampler;
    if (noise) text += tr(" · noise ≈ %1%").arg(*noise * 100.0, 0, 'f', *noise < 0.1 ? 2 : 1);
    if (!frame.deviceName.isEmpty()) text += QStringLiteral(" · ") + frame.deviceName;
    // Which preview is on screen: a drag's approximate first answer or the exact one after it.
    if (frame.kind == RenderFrame::Kind::Relight)
        text += frame.approximate ? tr(" · approximate first answer") : tr(" · exact preview");
    // What the last edit cost (architecture.md §5.B): a light drag should read "uploaded: lights".
    if (!frame.lastUpdate.isEmpty()) text += QStringLiteral(" — ") + frame.lastUpdate;
    return text;
}

void RenderStatusLabel::showFrame(const RenderFrame& frame) {
    m_estimator.add(frame.image, frame.samplesPerPixel, frame.generation);
    m_noise = m_estimator.relativeNoise(frame.samplesPerPixel);
    setText(format(frame, m_sampler, m_noise));
}

void RenderStatusLabel::showState(const QString& text) { setText(text); }

} // namespace wavelit::editor
