#include "viewport/gizmo_painter.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPolygonF>

namespace wavelit::editor {
namespace {
const QColor kAxisColours[3] = {QColor(230, 60, 60), QColor(80, 200, 80), QColor(70, 120, 240)};
const QColor kShapeColour(255, 220, 120);

QPolygonF polygon(const std::vector<glm::vec2>& points, const ImageToWidget& toWidget) {
    QPolygonF out;
    for (const glm::vec2& p : points) out << toWidget(p);
    return out;
}
} // namespace

void paintRotateGizmo(QPainter& painter, const RotateGeometry& gizmo, const ImageToWidget& toWidget) {
    painter.setBrush(Qt::NoBrush);
    for (const RotateRing& ring : gizmo.rings) {
        painter.setPen(QPen(kAxisColours[ring.axis], 2.0));
        painter.drawPolygon(polygon(ring.points, toWidget));
    }
    painter.setPen(QPen(Qt::white, 1.5));
    painter.drawEllipse(toWidget(gizmo.centre), 3.0, 3.0);
}

void paintManipulators(QPainter& painter, const ManipulatorGeometry& shape, const ImageToWidget& toWidget) {
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(kShapeColour, 1.0, Qt::DashLine));
    for (const auto& outline : shape.outlines) painter.drawPolygon(polygon(outline, toWidget));
    for (const auto& [a, b] : shape.lines) painter.drawLine(toWidget(a), toWidget(b));
    painter.setPen(QPen(QColor(20, 20, 20), 1.0));
    painter.setBrush(kShapeColour);
    for (const ManipulatorHandle& h : shape.handles) {
        const QPointF p = toWidget(h.pixel);
        painter.drawRect(QRectF(p.x() - 3.5, p.y() - 3.5, 7.0, 7.0));
    }
}

void paintOverlayMessage(QPainter& painter, const QString& message, QPointF at, const QRectF& bounds) {
    if (message.isEmpty()) return;
    const QFontMetrics metrics(painter.font());
    QRectF box = QRectF(metrics.boundingRect(message)).adjusted(-5, -3, 5, 3);
    box.moveTopLeft(at + QPointF(12, 12));
    if (box.right() > bounds.right()) box.moveRight(bounds.right());
    if (box.bottom() > bounds.bottom()) box.moveBottom(bounds.bottom());
    if (box.left() < bounds.left()) box.moveLeft(bounds.left());
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(120, 20, 20, 220));
    painter.drawRect(box);
    painter.setPen(Qt::white);
    painter.drawText(box, Qt::AlignCenter, message);
}

} // namespace wavelit::editor
