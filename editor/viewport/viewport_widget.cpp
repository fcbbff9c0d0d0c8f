#include "viewport/viewport_widget.h"

#include "viewport/tone_map.h"

#include <QPainter>

namespace wavelit::editor {
namespace {
const QColor kBackground(38, 38, 42);
} // namespace

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent) {
    setObjectName("viewport");
    setMinimumSize(64, 64);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void ViewportWidget::showFrame(const RenderFrame& frame) {
    m_frame = frame;
    m_display = frame.display;
    if (m_display.isNull() && frame.image) { // a frame made without its display form
        m_display = toneMap(*frame.image, m_exposureEv);
        m_frame.displayExposureEv = m_exposureEv;
    }
    update();
}

void ViewportWidget::clear() {
    m_frame = RenderFrame{};
    m_display = QImage();
    update();
}

void ViewportWidget::setExposure(float ev) {
    if (ev == m_exposureEv) return;
    m_exposureEv = ev;
    emit exposureChanged(ev);
}

void ViewportWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    if (m_display.isNull()) return;
    QSize fitted = m_display.size().scaled(size(), Qt::KeepAspectRatio);
    QRect target(QPoint((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
    // Enlarging a small preview smoothly blurs noise; nearest keeps the pixels honest.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, fitted.width() < m_display.width());
    painter.drawImage(target, m_display);
}

} // namespace wavelit::editor
