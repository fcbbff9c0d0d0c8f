#include "viewport/camera_orbit_handler.h"

#include <QMouseEvent>
#include <QWheelEvent>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::editor {

scene::Camera orbitCamera(const scene::Camera& camera, float yawDeg, float pitchDeg) {
    const glm::vec3 offset = camera.position - camera.target;
    const float distance = glm::length(offset);
    if (distance < kMinDistance) return camera;
    // Spherical coordinates about +Y (architecture.md §3: +Y up).
    const float pitch = glm::degrees(std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f)));
    const float yaw = glm::degrees(std::atan2(offset.x, offset.z));
    const float newPitch = glm::radians(std::clamp(pitch + pitchDeg, -kMaxPitchDeg, kMaxPitchDeg));
    const float newYaw = glm::radians(yaw + yawDeg);
    scene::Camera out = camera;
    out.position = camera.target + distance * glm::vec3(std::cos(newPitch) * std::sin(newYaw),
                                                        std::sin(newPitch),
                                                        std::cos(newPitch) * std::cos(newYaw));
    return out;
}

scene::Camera dollyCamera(const scene::Camera& camera, float factor) {
    const glm::vec3 offset = camera.position - camera.target;
    const float distance = glm::length(offset);
    if (distance < kMinDistance || !(factor > 0.0f)) return camera;
    scene::Camera out = camera;
    out.position = camera.target + offset * (std::max(distance * factor, kMinDistance) / distance);
    return out;
}

scene::Camera panCamera(const scene::Camera& camera, float right, float up) {
    const glm::vec3 offset = camera.position - camera.target;
    const float distance = glm::length(offset);
    if (distance < kMinDistance) return camera;
    const glm::vec3 forward = -offset / distance;
    const glm::vec3 r = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 u = glm::cross(r, forward);
    const glm::vec3 shift = distance * (right * r + up * u);
    scene::Camera out = camera;
    out.position += shift;
    out.target += shift;
    return out;
}

CameraOrbitHandler::CameraOrbitHandler(QObject* parent) : QObject(parent) {}

void CameraOrbitHandler::setCamera(const scene::Camera& camera) {
    m_camera = camera;
    m_hasCamera = true;
}

bool CameraOrbitHandler::eventFilter(QObject* watched, QEvent* event) {
    if (!m_hasCamera) return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (m_dragging || (mouse->button() != Qt::LeftButton && mouse->button() != Qt::MiddleButton)) break;
        m_panning = mouse->button() == Qt::MiddleButton || (mouse->modifiers() & Qt::ShiftModifier);
        m_button = mouse->button();
        m_dragging = true;
        m_gestures.begin();
        m_dragStart = m_camera;
        m_pressPos = mouse->position();
        return true;
    }
    case QEvent::MouseMove: {
        if (!m_dragging) break;
        const QPointF delta = static_cast<QMouseEvent*>(event)->position() - m_pressPos;
        if (m_panning) {
            // The scene follows the mouse: the camera moves against it.
            m_camera = panCamera(m_dragStart, -float(delta.x()) * kPanPerPixel, float(delta.y()) * kPanPerPixel);
            emit viewMoved(m_camera.position, m_camera.target, m_gestures.current());
            return true;
        }
        // Dragging right turns the view right: the camera moves the other way round the target.
        m_camera = orbitCamera(m_dragStart, -float(delta.x()) * kOrbitDegPerPixel,
                               float(delta.y()) * kOrbitDegPerPixel);
        emit cameraMoved(m_camera.position, m_gestures.current());
        return true;
    }
    case QEvent::MouseButtonRelease:
        if (!m_dragging || static_cast<QMouseEvent*>(event)->button() != m_button) break;
        m_dragging = false;
        m_panning = false;
        m_gestures.end();
        return true;
    case QEvent::Wheel: {
        const float notches = float(static_cast<QWheelEvent*>(event)->angleDelta().y()) / 120.0f;
        if (notches == 0.0f) break;
        m_camera = dollyCamera(m_camera, std::pow(kDollyPerWheelStep, notches));
        m_gestures.scrub();
        emit cameraMoved(m_camera.position, m_gestures.current());
        return true;
    }
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace wavelit::editor
