// Drawing of the viewport's rotate rings and light shape handles (rotate_gizmo.h,
// light_manipulators.h) over the image, and of a refusal message beside them. Geometry comes in
// image pixels; `toWidget` maps it to the painter's (widget) coordinates.
#pragma once

#include "viewport/light_manipulators.h"
#include "viewport/rotate_gizmo.h"

#include <QPointF>
#include <QString>

#include <functional>

class QPainter;

namespace wavelit::editor {

using ImageToWidget = std::function<QPointF(glm::vec2)>;

void paintRotateGizmo(QPainter& painter, const RotateGeometry& gizmo, const ImageToWidget& toWidget);
void paintManipulators(QPainter& painter, const ManipulatorGeometry& shape, const ImageToWidget& toWidget);
// A short message in a dark box near `at` (widget coordinates), kept inside `bounds`.
void paintOverlayMessage(QPainter& painter, const QString& message, QPointF at, const QRectF& bounds);

} // namespace wavelit::editor
