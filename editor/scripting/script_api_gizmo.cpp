// AppApi's gizmo calls (docs/scripting.md "Gizmo modes, shape handles, cross-fade"; issue 14):
// the gizmo mode, where the selection's rings and shape handles are drawn (so a test drags them
// through dragInViewport's real mouse events), the refusal a clamped drag shows, and the viewport
// as painted (the preview -> path-traced cross-fade).
#include "scripting/script_api.h"

#include "app/main_window.h"
#include "app/scene_document.h"
#include "viewport/render_controller.h"
#include "viewport/light_manipulators.h"
#include "viewport/rotate_gizmo.h"
#include "viewport/view_projection.h"
#include "viewport/viewport_interaction.h"
#include "viewport/viewport_widget.h"

#include <QJSEngine>
#include <QPixmap>

#include <cmath>

namespace wavelit::editor {
namespace {

QJSValue pair(QJSEngine* engine, double x, double y) {
    QJSValue out = engine->newArray(2);
    out.setProperty(quint32(0), x);
    out.setProperty(quint32(1), y);
    return out;
}

double luminance(QRgb c) { return 0.2126 * qRed(c) + 0.7152 * qGreen(c) + 0.0722 * qBlue(c); }

} // namespace

bool AppApi::setGizmoMode(const QString& mode) {
    const auto parsed = gizmoModeFromName(mode.toStdString());
    if (!parsed) return fail(QStringLiteral("setGizmoMode: expected \"move\" or \"rotate\", not \"%1\"").arg(mode));
    m_window->interaction()->setGizmoMode(*parsed);
    return true;
}

QString AppApi::gizmoMode() const { return gizmoModeName(m_window->interaction()->gizmoMode()); }

QJSValue AppApi::gizmoInfo() {
    ViewportInteraction* interaction = m_window->interaction();
    ViewportWidget* viewport = m_window->viewport();
    auto scene = m_window->document()->scene();
    const QSize size = viewport->imageSize();
    if (!scene || size.isEmpty()) return fail("gizmoInfo: the viewport shows no image yet"), QJSValue();
    const auto selection = interaction->selection();
    if (!selection) return fail("gizmoInfo: nothing is selected"), QJSValue();
    const ViewProjection view(scene->camera, size.width(), size.height());
    const float pxScale = viewport->imagePixelsPerScreenPixel();
    QJSValue out = m_engine->newObject();
    out.setProperty("mode", gizmoMode());
    out.setProperty("ringRadius", double(kRingRadiusPx * pxScale));
    QJSValue rings = m_engine->newObject();
    if (interaction->gizmoMode() == GizmoMode::Rotate)
        if (auto g = rotateGeometry(*scene, *selection, view, pxScale))
            for (const RotateRing& ring : g->rings) {
                QJSValue r = m_engine->newObject();
                const glm::vec2 p = ring.points[ring.grabIndex], t = ring.tangents[ring.grabIndex];
                r.setProperty("point", pair(m_engine, p.x, p.y));
                r.setProperty("tangent", pair(m_engine, t.x, t.y));
                rings.setProperty(QString(QChar("xyz"[ring.axis])), r);
            }
    out.setProperty("rings", rings);
    QJSValue handles = m_engine->newObject();
    if (auto shape = manipulatorGeometry(*scene, *selection, view, pxScale))
        for (const ManipulatorHandle& h : shape->handles)
            handles.setProperty(manipulatorName(h.kind), pair(m_engine, h.pixel.x, h.pixel.y));
    out.setProperty("handles", handles);
    return out;
}

QString AppApi::viewportMessage() const { return m_window->viewport()->overlayMessage(); }

QJSValue AppApi::projectToViewport(const QJSValue& point) {
    auto scene = m_window->document()->scene();
    const QSize size = m_window->viewport()->imageSize();
    if (!scene || size.isEmpty()) return fail("projectToViewport: the viewport shows no image yet"), QJSValue();
    if (!point.isArray() || point.property("length").toInt() != 3)
        return fail("projectToViewport: expected a world point [x, y, z]"), QJSValue();
    const glm::vec3 world(float(point.property(0).toNumber()), float(point.property(1).toNumber()),
                          float(point.property(2).toNumber()));
    const auto p = ViewProjection(scene->camera, size.width(), size.height()).project(world);
    return p ? pair(m_engine, p->x, p->y) : QJSValue(QJSValue::NullValue);
}

bool AppApi::setCrossFadeMs(int ms) {
    if (ms < 0) return fail(QStringLiteral("setCrossFadeMs: %1 ms is negative").arg(ms));
    m_window->viewport()->setCrossFadeMs(ms);
    return true;
}

QJSValue AppApi::viewportPixels(const QString& which) {
    ViewportWidget* viewport = m_window->viewport();
    const QRectF shown = viewport->imageRect();
    if (shown.isEmpty()) return fail("viewportPixels: the viewport shows no image yet"), QJSValue();
    // Painted: sampled on the render size's grid (a ¼-size draft on screen is read on the same
    // grid as the path-traced image it fades into).
    const RenderSettings& settings = m_window->renderer()->settings();
    const bool painted = which.isEmpty() || which == "painted";
    const QSize size = painted && settings.width > 0 && settings.height > 0 ? QSize(settings.width, settings.height)
                                                                           : viewport->imageSize();
    QImage image;
    double fade = -1.0;
    if (painted) {
        image = viewport->grab().toImage(); // paints now: the fade at this instant
        fade = viewport->lastPaintedFade();
    } else if (which == "frame") {
        image = viewport->displayedImage();
    } else {
        return fail(QStringLiteral("viewportPixels: expected \"painted\" or \"frame\", not \"%1\"").arg(which)),
               QJSValue();
    }
    QJSValue lum = m_engine->newArray(quint32(size.width() * size.height()));
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            QPoint at(x, y);
            if (painted) {
                const QPointF w(shown.x() + (x + 0.5) * shown.width() / size.width(),
                                shown.y() + (y + 0.5) * shown.height() / size.height());
                at = QPoint(int(std::floor(w.x())), int(std::floor(w.y())));
            }
            lum.setProperty(quint32(y * size.width() + x), luminance(image.pixel(at)));
        }
    QJSValue out = m_engine->newObject();
    out.setProperty("fade", fade);
    out.setProperty("luminance", lum);
    return out;
}

} // namespace wavelit::editor
