// MoveGizmo: the move handle of the selected light or object, as geometry in image pixels
// (view_projection.h) and the drag that follows the mouse. Parts: the centre square moves in the
// plane facing the camera through the handle; the three axis arrows (+X red, +Y green, +Z blue,
// kAxisLengthPx long on screen) move along one world axis; a sun (a direction, no position) is
// dragged over a sphere round the camera target (scene_picker.h sunHandleDistance) and its
// direction points from the handle to the target. No Qt: the interaction handler feeds it image
// points and turns the result into property edits.
#pragma once

#include "panels/entity_ref.h"
#include "viewport/view_projection.h"

#include "scene/scene.h"

#include <array>
#include <optional>

namespace wavelit::editor {

inline constexpr float kAxisLengthPx = 60.0f;
inline constexpr float kGizmoGrabPx = 7.0f;

enum class GizmoPart { None, Centre, AxisX, AxisY, AxisZ, SunSphere };

struct GizmoGeometry {
    glm::vec2 centre;
    std::array<std::optional<glm::vec2>, 3> axisTips; // nullopt: the axis points at the camera
    bool sun = false;
};

// The handle of `ref` as drawn; nullopt when the entity has no handle or it is behind the camera.
// Sizes (kAxisLengthPx, kGizmoGrabPx) are screen pixels; `pxScale` is image pixels per screen
// pixel (the viewport scales the image to fit).
std::optional<GizmoGeometry> gizmoGeometry(const scene::Scene& scene, EntityRef ref, const ViewProjection& view,
                                           float pxScale);
// Which part of the gizmo is under `pixel`.
GizmoPart hitGizmo(const GizmoGeometry& gizmo, glm::vec2 pixel, float pxScale);

// One drag of one part: created at the press with the handle's world position, then asked for
// the world position (or sun direction) under each later mouse position.
class GizmoDrag {
public:
    GizmoDrag(GizmoPart part, const scene::Scene& scene, EntityRef ref, const ViewProjection& view,
              glm::vec2 pressPixel);
    bool valid() const { return m_valid; }
    EntityRef entity() const { return m_entity; }
    GizmoPart part() const { return m_part; }
    // The handle's new world position for the mouse at `pixel` (the press point maps to the start).
    glm::vec3 positionAt(glm::vec2 pixel) const;
    // A sun's new direction (the way its light travels, unit) for the mouse at `pixel`.
    glm::vec3 sunDirectionAt(glm::vec2 pixel) const;

private:
    std::optional<glm::vec3> onDragPlane(glm::vec2 pixel) const;
    GizmoPart m_part;
    EntityRef m_entity;
    ViewProjection m_view;
    glm::vec3 m_start{0.0f};      // handle position at the press
    glm::vec3 m_pressPoint{0.0f}; // the press ray on the drag plane
    glm::vec3 m_planeNormal{0.0f};
    glm::vec3 m_axis{0.0f};
    glm::vec3 m_sunCentre{0.0f};
    float m_sunRadius = 1.0f;
    bool m_valid = false;
};

} // namespace wavelit::editor
