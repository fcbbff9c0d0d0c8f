#include "viewport/viewport_widget.h"

#include "viewport/gizmo_painter.h"
#include "viewport/light_manipulators.h"
#include "viewport/move_gizmo.h"
#include "viewport/rotate_gizmo.h"
#include "viewport/scene_picker.h"
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
    setFocusPolicy(Qt::ClickFocus); // F frames the selection (viewport_interaction.h)
    m_fadeTimer.setInterval(16);
    connect(&m_fadeTimer, &QTimer::timeout, this, qOverload<>(&QWidget::update));
}

void ViewportWidget::showFrame(const RenderFrame& frame) {
    const bool wasPreview = m_frame.kind != RenderFrame::Kind::PathTraced;
    if (frame.kind != RenderFrame::Kind::PathTraced) stopFade(); // a new edit's preview: no lingering
    else if (wasPreview && !m_display.isNull() && m_fadeMs > 0 && frame.generation >= m_frame.generation) {
        m_fadeFrom = m_display; // implicitly shared: no copy
        m_fadeClock.start();
        m_fadeTimer.start();
    }
    m_frame = frame;
    m_display = frame.display;
    if (m_display.isNull() && frame.image) { // a frame made without its display form
        m_display = toneMap(*frame.image, m_exposureEv);
        m_frame.displayExposureEv = m_exposureEv;
    }
    update();
}

void ViewportWidget::stopFade() {
    m_fadeFrom = QImage();
    m_fadeTimer.stop();
}

void ViewportWidget::clear() {
    stopFade();
    m_frame = RenderFrame{};
    m_display = QImage();
    update();
}

void ViewportWidget::setExposure(float ev) {
    if (ev == m_exposureEv) return;
    m_exposureEv = ev;
    emit exposureChanged(ev);
}

QRectF ViewportWidget::imageRect() const {
    if (m_display.isNull()) return {};
    QSize fitted = m_display.size().scaled(size(), Qt::KeepAspectRatio);
    return QRectF(QPointF((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
}

std::optional<QPointF> ViewportWidget::widgetToImage(QPointF p) const {
    const QRectF r = imageRect();
    if (r.isEmpty() || !r.contains(p)) return std::nullopt;
    return QPointF((p.x() - r.x()) * m_display.width() / r.width(),
                   (p.y() - r.y()) * m_display.height() / r.height());
}

QPointF ViewportWidget::imageToWidget(QPointF p) const {
    const QRectF r = imageRect();
    if (r.isEmpty()) return p;
    return QPointF(r.x() + p.x() * r.width() / m_display.width(), r.y() + p.y() * r.height() / m_display.height());
}

float ViewportWidget::imagePixelsPerScreenPixel() const {
    const QRectF r = imageRect();
    return r.isEmpty() ? 1.0f : float(m_display.width() / r.width());
}

void ViewportWidget::setOverlay(std::shared_ptr<const scene::Scene> scene, std::optional<EntityRef> selection) {
    m_overlayScene = std::move(scene);
    m_selection = selection;
    update();
}

void ViewportWidget::setGizmoMode(GizmoMode mode) {
    m_gizmoMode = mode;
    update();
}

void ViewportWidget::setOverlayMessage(const QString& message) {
    m_overlayMessage = message;
    update();
}

void ViewportWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    if (m_display.isNull()) return;
    const QRectF target = imageRect();
    // Enlarging a small preview smoothly blurs noise; nearest keeps the pixels honest.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < m_display.width());
    m_lastPaintedFade = -1.0;
    if (!m_fadeFrom.isNull()) {
        const double t = double(m_fadeClock.nsecsElapsed()) * 1e-6 / double(std::max(m_fadeMs, 1));
        if (t >= 1.0) stopFade();
        else {
            painter.drawImage(target, m_fadeFrom);
            painter.setOpacity(t);
            m_lastPaintedFade = t;
        }
    }
    painter.drawImage(target, m_display);
    painter.setOpacity(1.0);
    paintOverlay(painter);
}

void ViewportWidget::paintOverlay(QPainter& painter) const {
    if (!m_overlayScene) return;
    const scene::Scene& scene = *m_overlayScene;
    const ViewProjection view(scene.camera, m_display.width(), m_display.height());
    auto toWidget = [&](glm::vec2 p) { return imageToWidget(QPointF(p.x, p.y)); };
    const float pxScale = imagePixelsPerScreenPixel();
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (const auto& light : scene.lighting.lights) {
        const auto world = handlePosition(scene, {EntityKind::Light, light.id});
        const auto p = world ? view.project(*world) : std::nullopt;
        if (!p) continue;
        painter.setPen(QPen(QColor(20, 20, 20), 1.5));
        painter.setBrush(light.type == scene::LightType::Sun ? QColor(255, 200, 60) : QColor(255, 240, 160));
        painter.drawEllipse(toWidget(*p), 4.0, 4.0);
    }
    if (!m_selection) return;
    if (auto shape = manipulatorGeometry(scene, *m_selection, view, pxScale))
        paintManipulators(painter, *shape, toWidget);
    if (const auto anchor = handlePosition(scene, *m_selection); anchor && !m_overlayMessage.isEmpty())
        if (const auto p = view.project(*anchor)) paintOverlayMessage(painter, m_overlayMessage, toWidget(*p), rect());
    const bool sun = gizmoGeometry(scene, *m_selection, view, pxScale).value_or(GizmoGeometry{}).sun;
    if (m_gizmoMode == GizmoMode::Rotate && !sun) {
        if (auto rings = rotateGeometry(scene, *m_selection, view, pxScale)) paintRotateGizmo(painter, *rings, toWidget);
        return; // nothing to turn (a point or sphere light): no move gizmo either, the mode says rotate
    }
    const auto gizmo = gizmoGeometry(scene, *m_selection, view, pxScale);
    if (!gizmo) return;
    const QPointF centre = toWidget(gizmo->centre);
    const QColor axisColours[3] = {QColor(230, 60, 60), QColor(80, 200, 80), QColor(70, 120, 240)};
    for (size_t a = 0; a < 3; ++a) {
        if (!gizmo->axisTips[a]) continue;
        painter.setPen(QPen(axisColours[a], 2.5));
        painter.drawLine(centre, toWidget(*gizmo->axisTips[a]));
    }
    painter.setPen(QPen(Qt::white, 1.5));
    painter.setBrush(Qt::NoBrush);
    const double r = kGizmoGrabPx + 3.0; // screen pixels
    if (gizmo->sun)
        painter.drawEllipse(centre, r, r);
    else
        painter.drawRect(QRectF(centre.x() - r * 0.6, centre.y() - r * 0.6, r * 1.2, r * 1.2));
}

} // namespace wavelit::editor
