// ViewportInteraction: the viewport's selection, gizmo and environment interaction, one event
// filter installed on the ViewportWidget after CameraOrbitHandler (so it sees each event first
// and passes on what it does not handle):
//   click (press and release within kClickSlopPx)   select what is under the cursor (picking:
//                                                   scene_picker.h); empty space clears it;
//   left-drag on the selection's gizmo              move mode (W): move the light/object
//                                                   (move_gizmo.h), or turn a sun by dragging
//                                                   its handle; rotate mode (E): turn an object
//                                                   or a spot/rect light about a world axis
//                                                   (rotate_gizmo.h); in both, a light's shape
//                                                   handles (light_manipulators.h: radius,
//                                                   size, cone) edit its shape, clamped to the
//                                                   registry's range (clampNotice says so);
//   Ctrl + left-drag                                rotate the environment: a horizontal drag
//                                                   across the whole image is
//                                                   kEnvDegPerImageWidth, whatever the zoom;
//   W / E (the viewport focused)                    move / rotate gizmo (setGizmoMode);
//   F (the viewport focused)                        frame the selection: the camera looks at it
//                                                   from its current side, an object filling
//                                                   about 2/3 of the view height;
//   anything else                                   the camera handler (orbit, pan, zoom).
// A drag is one gesture (one undo step). dragActiveChanged(true/false) brackets every viewport
// drag (also the camera's) so the renderer can show its fastest honest image while it lasts.
#pragma once

#include "commands/property_edit.h"
#include "panels/gesture_tracker.h"
#include "viewport/gizmo_mode.h"
#include "viewport/light_manipulators.h"
#include "viewport/move_gizmo.h"
#include "viewport/rotate_gizmo.h"
#include "viewport/scene_picker.h"

#include <QObject>
#include <QPointF>

#include <memory>
#include <optional>

namespace wavelit::editor {

class ViewportWidget;

inline constexpr float kClickSlopPx = 3.0f;    // widget pixels a click may wander
inline constexpr float kEnvDegPerImageWidth = 180.0f; // environment yaw per image width of drag

class ViewportInteraction : public QObject {
    Q_OBJECT
public:
    explicit ViewportInteraction(ViewportWidget* viewport, QObject* parent = nullptr);

    void setScene(std::shared_ptr<const scene::Scene> scene);
    void setSelection(std::optional<EntityRef> ref);
    std::optional<EntityRef> selection() const { return m_selection; }
    // What a click at this image point would select (nullopt: nothing, i.e. the environment).
    std::optional<EntityRef> pickAt(QPointF imagePoint);
    bool isDragging() const { return m_mode != Mode::Idle; }
    // Frame the selection (the F key): emits viewRequested; false when nothing framable is selected.
    bool frameSelected();
    void setGizmoMode(GizmoMode mode);
    GizmoMode gizmoMode() const { return m_gizmoMode; }
    // The message of the last clamped manipulator drag ("" when the last drag was not clamped).
    const QString& lastClamp() const { return m_lastClamp; }

signals:
    void editRequested(const wavelit::editor::PropertyEdit& edit);
    void selectRequested(std::optional<wavelit::scene::EntityRef> ref);
    void dragActiveChanged(bool active);
    void viewRequested(const glm::vec3& position, const glm::vec3& target);
    void gizmoModeChanged(wavelit::editor::GizmoMode mode);
    // A manipulator drag asked for a value outside the property's range and was held at the limit
    // (the message names the property, the value asked for, the range and the value kept); ""
    // when a later move is inside the range again.
    void clampNotice(const QString& message);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class Mode { Idle, Camera, Gizmo, Environment };
    bool press(QObject* watched, QEvent* event);
    bool move(QEvent* event);
    bool release(QEvent* event);
    bool pressGizmo(glm::vec2 image); // the selection's gizmo or shape handles under the press
    std::optional<QPointF> imagePoint(QPointF widgetPoint) const;

    ViewportWidget* m_viewport;
    std::shared_ptr<const scene::Scene> m_scene;
    std::optional<EntityRef> m_selection;
    ScenePicker m_picker;
    GestureTracker m_gestures;
    Mode m_mode = Mode::Idle;
    QPointF m_pressWidget;
    QPointF m_pressImage;
    bool m_moved = false;
    std::optional<GizmoDrag> m_drag;
    std::optional<RotateDrag> m_rotate;
    std::optional<ManipulatorDrag> m_manipulator;
    GizmoMode m_gizmoMode = GizmoMode::Move;
    QString m_lastClamp;
    float m_envStartDeg = 0.0f;
};

} // namespace wavelit::editor
