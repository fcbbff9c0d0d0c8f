// CameraOrbitHandler: the viewport's camera interaction, one event filter (the appleseed model:
// one small handler class per interaction). Left-drag orbits the camera about its target (yaw
// about +Y, pitch clamped short of the poles so `up` stays valid); the wheel dollies toward the
// target; a middle-drag or Shift + left-drag pans (camera and target move together in the view
// plane, kPanPerPixel of the target distance per widget pixel). The handler only proposes a camera position through cameraMoved; the document turns it
// into a registry edit (a Restart change) and the render thread picks the newest one up between
// passes, so a fast drag costs one restart per pass, not one per mouse event. A drag, or a run of
// wheel notches, is one gesture: it undoes in one step.
#pragma once

#include "panels/gesture_tracker.h"
#include "scene/scene.h"

#include <QObject>
#include <QPointF>

namespace wavelit::editor {

inline constexpr float kMaxPitchDeg = 85.0f;       // keeps the view direction away from +-up
inline constexpr float kOrbitDegPerPixel = 0.4f;
inline constexpr float kDollyPerWheelStep = 0.9f;  // distance factor per 15-degree wheel notch
inline constexpr float kMinDistance = 1e-3f;
inline constexpr float kPanPerPixel = 0.0015f;     // of the target distance, per widget pixel

// The camera moved on its orbit sphere: distance to the target unchanged, pitch clamped.
scene::Camera orbitCamera(const scene::Camera& camera, float yawDeg, float pitchDeg);
// The camera moved toward the target by `factor` of its distance (< 1 closer), never onto it.
scene::Camera dollyCamera(const scene::Camera& camera, float factor);
// The camera and its target moved together by (right, up) in the view plane, in units of the
// target distance.
scene::Camera panCamera(const scene::Camera& camera, float right, float up);

class CameraOrbitHandler : public QObject {
    Q_OBJECT
public:
    explicit CameraOrbitHandler(QObject* parent = nullptr);

    // The camera the next drag starts from (the document's current camera).
    void setCamera(const scene::Camera& camera);
    bool isDragging() const { return m_dragging; }

signals:
    void cameraMoved(const glm::vec3& position, wavelit::editor::GestureId gesture);
    // A pan: position and target both changed (one gesture).
    void viewMoved(const glm::vec3& position, const glm::vec3& target, wavelit::editor::GestureId gesture);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    GestureTracker m_gestures;
    scene::Camera m_camera;
    scene::Camera m_dragStart;
    QPointF m_pressPos;
    bool m_hasCamera = false;
    bool m_dragging = false;
    bool m_panning = false;
    Qt::MouseButton m_button = Qt::NoButton;
};

} // namespace wavelit::editor
