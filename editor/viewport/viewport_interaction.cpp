#include "viewport/viewport_interaction.h"

#include "viewport/viewport_widget.h"

#include <QKeyEvent>
#include <QMouseEvent>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace wavelit::editor {
namespace {
glm::vec2 toGlm(QPointF p) { return {float(p.x()), float(p.y())}; }

// The world-space bounding sphere of an object's mesh (centre of its box, farthest vertex).
std::optional<std::pair<glm::vec3, float>> objectBounds(const scene::Object& object) {
    if (!object.mesh || object.mesh->positions.empty()) return std::nullopt;
    const glm::mat4 m = object.transform.matrix();
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : object.mesh->positions) {
        const glm::vec3 w = glm::vec3(m * glm::vec4(p, 1.0f));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    return std::make_pair(centre, glm::length(hi - centre));
}
} // namespace

ViewportInteraction::ViewportInteraction(ViewportWidget* viewport, QObject* parent)
    : QObject(parent), m_viewport(viewport) {}

void ViewportInteraction::setScene(std::shared_ptr<const scene::Scene> scene) {
    m_scene = std::move(scene);
    m_viewport->setOverlay(m_scene, m_selection);
}

void ViewportInteraction::setSelection(std::optional<EntityRef> ref) {
    m_selection = ref;
    m_viewport->setOverlay(m_scene, m_selection);
}

std::optional<QPointF> ViewportInteraction::imagePoint(QPointF widgetPoint) const {
    return m_viewport->widgetToImage(widgetPoint);
}

std::optional<EntityRef> ViewportInteraction::pickAt(QPointF point) {
    const QSize size = m_viewport->imageSize();
    if (!m_scene || size.isEmpty()) return std::nullopt;
    return m_picker.pick(m_scene, size.width(), size.height(), toGlm(point), m_viewport->imagePixelsPerScreenPixel());
}

bool ViewportInteraction::frameSelected() {
    if (!m_scene || !m_selection) return false;
    const scene::Camera& camera = m_scene->camera;
    glm::vec3 target;
    float distance = glm::length(camera.position - camera.target);
    if (m_selection->kind == EntityKind::Object) {
        std::optional<std::pair<glm::vec3, float>> bounds;
        for (const auto& object : m_scene->objects)
            if (object.id == m_selection->id) bounds = objectBounds(object);
        if (!bounds) return false;
        target = bounds->first;
        // The bounding sphere fills ~2/3 of the vertical field of view.
        distance = std::max(1.5f * bounds->second / std::sin(0.5f * glm::radians(camera.verticalFovDeg)), 1e-2f);
    } else if (auto handle = handlePosition(*m_scene, *m_selection)) {
        target = *handle;
    } else {
        return false;
    }
    glm::vec3 back = camera.position - camera.target;
    back = glm::length(back) > 0.0f ? glm::normalize(back) : glm::vec3(0, 0, 1);
    emit viewRequested(target + back * distance, target);
    return true;
}

bool ViewportInteraction::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::KeyPress: {
        const auto* keyEvent = static_cast<QKeyEvent*>(event);
        const int key = keyEvent->key();
        if (m_mode != Mode::Idle) return false;
        if (keyEvent->modifiers() != Qt::NoModifier && key != Qt::Key_F) return false; // Ctrl+E is not E
        if (key == Qt::Key_F) frameSelected();
        else if (key == Qt::Key_W) setGizmoMode(GizmoMode::Move);   // as Blender and Maya
        else if (key == Qt::Key_E) setGizmoMode(GizmoMode::Rotate);
        else return false;
        return true;
    }
    case QEvent::MouseButtonPress: return press(watched, event);
    case QEvent::MouseMove: return move(event);
    case QEvent::MouseButtonRelease: return release(event);
    default: return QObject::eventFilter(watched, event);
    }
}

bool ViewportInteraction::press(QObject*, QEvent* event) {
    auto* mouse = static_cast<QMouseEvent*>(event);
    if (m_mode != Mode::Idle || !m_scene) return false;
    m_pressWidget = mouse->position();
    m_moved = false;
    if (!m_lastClamp.isEmpty()) { // the refusal stays in view until the next press
        m_lastClamp.clear();
        m_viewport->setOverlayMessage({});
    }
    const auto image = imagePoint(mouse->position());
    m_pressImage = image.value_or(QPointF());
    if (mouse->button() == Qt::LeftButton && image && (mouse->modifiers() & Qt::ControlModifier)) {
        m_mode = Mode::Environment;
        m_envStartDeg = m_scene->lighting.environment.rotationDeg;
        m_gestures.begin();
        emit dragActiveChanged(true);
        return true;
    }
    if (mouse->button() == Qt::LeftButton && image && m_selection && pressGizmo(toGlm(*image))) {
        m_mode = Mode::Gizmo;
        m_gestures.begin();
        emit dragActiveChanged(true);
        return true;
    }
    // The camera handler takes it (orbit, pan); a release without motion is a click.
    m_mode = Mode::Camera;
    emit dragActiveChanged(true);
    return false;
}

void ViewportInteraction::setGizmoMode(GizmoMode mode) {
    if (mode == m_gizmoMode) return;
    m_gizmoMode = mode;
    m_viewport->setGizmoMode(mode);
    emit gizmoModeChanged(mode);
}

// Which handle a press takes, first to last: the move gizmo's centre square (moving is what a
// light is grabbed for most), a light's shape handles, then the mode's own parts (axis arrows,
// the sun's handle; or the rotate rings, a sun keeping its handle).
bool ViewportInteraction::pressGizmo(glm::vec2 image) {
    const QSize size = m_viewport->imageSize();
    const ViewProjection view(m_scene->camera, size.width(), size.height());
    const float pxScale = m_viewport->imagePixelsPerScreenPixel();
    const EntityRef ref = *m_selection;
    const auto moveGizmo = gizmoGeometry(*m_scene, ref, view, pxScale);
    const GizmoPart part = moveGizmo ? hitGizmo(*moveGizmo, image, pxScale) : GizmoPart::None;
    auto startMove = [&] {
        GizmoDrag drag(part, *m_scene, ref, view, image);
        if (drag.valid()) m_drag = drag;
        return drag.valid();
    };
    if (m_gizmoMode == GizmoMode::Move && part == GizmoPart::Centre) return startMove();
    if (auto shape = manipulatorGeometry(*m_scene, ref, view, pxScale)) {
        if (auto handle = hitManipulator(*shape, image, pxScale)) {
            ManipulatorDrag drag(*m_scene, ref, *handle, view, image);
            if (drag.valid()) {
                m_manipulator = drag;
                return true;
            }
        }
    }
    if (m_gizmoMode == GizmoMode::Move || part == GizmoPart::SunSphere)
        return part != GizmoPart::None && startMove();
    if (auto rings = rotateGeometry(*m_scene, ref, view, pxScale)) {
        if (auto hit = hitRotateRing(*rings, image, pxScale)) {
            RotateDrag drag(*m_scene, ref, *rings, hit->first, hit->second, image);
            if (drag.valid()) {
                m_rotate = drag;
                return true;
            }
        }
    }
    return false;
}

bool ViewportInteraction::move(QEvent* event) {
    auto* mouse = static_cast<QMouseEvent*>(event);
    if (m_mode == Mode::Idle) return false;
    if ((mouse->position() - m_pressWidget).manhattanLength() > kClickSlopPx) m_moved = true;
    if (m_mode == Mode::Camera) return false;
    const auto image = imagePoint(mouse->position());
    if (!image || !m_moved) return true;
    if (m_mode == Mode::Environment) {
        // Dragging right turns the environment with the mouse, as a globe under the hand.
        const float deg = m_envStartDeg + float(image->x() - m_pressImage.x()) /
                                              float(m_viewport->imageSize().width()) * kEnvDegPerImageWidth;
        const float wrapped = std::fmod(std::fmod(deg, 360.0f) + 360.0f, 360.0f);
        emit editRequested({{EntityKind::Environment, scene::kInvalidId}, "rotation", wrapped,
                            m_gestures.current()});
        return true;
    }
    if (m_mode == Mode::Gizmo && m_rotate) {
        emit editRequested({m_rotate->entity(), m_rotate->property(), m_rotate->valueAt(toGlm(*image)),
                            m_gestures.current()});
        return true;
    }
    if (m_mode == Mode::Gizmo && m_manipulator) {
        const ManipulatorValue v = m_manipulator->valueAt(toGlm(*image));
        const QString clamp = QString::fromStdString(v.clamped);
        if (clamp != m_lastClamp) {
            m_lastClamp = clamp;
            m_viewport->setOverlayMessage(clamp);
            emit clampNotice(clamp);
        }
        emit editRequested({m_manipulator->entity(), v.property, v.value, m_gestures.current()});
        return true;
    }
    if (m_mode == Mode::Gizmo && m_drag) {
        const EntityRef ref = m_drag->entity();
        if (m_drag->part() == GizmoPart::SunSphere)
            emit editRequested({ref, "direction", m_drag->sunDirectionAt(toGlm(*image)), m_gestures.current()});
        else
            emit editRequested({ref, ref.kind == EntityKind::Light ? "position" : "translation",
                                m_drag->positionAt(toGlm(*image)), m_gestures.current()});
    }
    return true;
}

bool ViewportInteraction::release(QEvent* event) {
    if (m_mode == Mode::Idle) return false;
    const Mode mode = m_mode;
    m_mode = Mode::Idle;
    m_drag.reset();
    m_rotate.reset();
    m_manipulator.reset();
    m_gestures.end();
    emit dragActiveChanged(false);
    if (mode != Mode::Camera) return true;
    auto* mouse = static_cast<QMouseEvent*>(event);
    if (!m_moved && mouse->button() == Qt::LeftButton) {
        if (const auto image = imagePoint(mouse->position())) emit selectRequested(pickAt(*image));
    }
    return false; // the camera handler ends its gesture too
}

} // namespace wavelit::editor
