// RotateGizmo: the rotate handle of the selected object or directed light (spot, rect, sun), as
// geometry in image pixels and the drag that turns it. Three rings round the handle, one per
// world axis (X red, Y green, Z blue), kRingRadiusPx on screen; dragging a ring turns the entity
// about that world axis through its handle. The angle is the mouse's travel along the ring's
// screen tangent at the grabbed point divided by the ring's screen radius (one ring radius of
// travel = 1 radian), so a ring seen nearly edge-on turns as predictably as one seen face-on.
// What turns: a light's `direction` (the way its light travels); an object's `rotation` (Euler
// XYZ degrees, scene.h Transform: R = Rz Ry Rx), as R' = R_axis(angle) R, re-expressed as Euler
// angles. Point and sphere lights have no direction: no rings. No Qt.
#pragma once

#include "panels/entity_ref.h"
#include "viewport/view_projection.h"

#include "scene/scene.h"

#include <array>
#include <optional>
#include <vector>

namespace wavelit::editor {

inline constexpr float kRingRadiusPx = 50.0f; // screen pixels
inline constexpr int kRingSegments = 48;

struct RotateRing {
    int axis = 0;                   // 0 X, 1 Y, 2 Z
    std::vector<glm::vec2> points;  // kRingSegments projected ring points (closed polyline)
    std::vector<glm::vec2> tangents; // unit screen tangent (increasing angle) at each point; 0 when end-on
    // Where scripts grab the ring: of the four points halfway between the world axes (the rings
    // cross on the axes), the one whose tangent is seen longest.
    size_t grabIndex = 0;
};

struct RotateGeometry {
    glm::vec2 centre{0.0f};
    std::vector<RotateRing> rings; // rings behind the camera are left out
    float ringRadiusImagePx = 0.0f;
};

// Whether `ref` can be turned: an object, or a light with a direction (spot, rect, sun).
bool rotatable(const scene::Scene& scene, EntityRef ref);
// The rings of `ref` as drawn; nullopt when it cannot be turned or is behind the camera.
// `pxScale`: image pixels per screen pixel.
std::optional<RotateGeometry> rotateGeometry(const scene::Scene& scene, EntityRef ref, const ViewProjection& view,
                                             float pxScale);
// The ring under `pixel` and the index of its nearest point; nullopt for none.
std::optional<std::pair<int, size_t>> hitRotateRing(const RotateGeometry& gizmo, glm::vec2 pixel, float pxScale);

class RotateDrag {
public:
    RotateDrag(const scene::Scene& scene, EntityRef ref, const RotateGeometry& gizmo, int ringIndex,
               size_t pointIndex, glm::vec2 pressPixel);
    bool valid() const { return m_valid; }
    EntityRef entity() const { return m_entity; }
    // The turn in radians for the mouse at `pixel` (right-handed about the ring's axis).
    float angleAt(glm::vec2 pixel) const;
    // The property the drag edits ("direction" or "rotation") and its value for the mouse at `pixel`.
    const char* property() const { return m_entity.kind == EntityKind::Light ? "direction" : "rotation"; }
    glm::vec3 valueAt(glm::vec2 pixel) const;

private:
    EntityRef m_entity;
    glm::vec3 m_axis{0.0f};
    glm::vec2 m_press{0.0f};
    glm::vec2 m_tangent{0.0f};
    float m_radiusPx = 1.0f;
    glm::vec3 m_startDirection{0.0f};
    glm::vec3 m_startRotationDeg{0.0f};
    bool m_valid = false;
};

// Euler XYZ degrees (R = Rz Ry Rx) of R_axis(angle) * R(start): an object turned about a world axis.
glm::vec3 rotateEulerDeg(const glm::vec3& startDeg, const glm::vec3& axis, float angle);

} // namespace wavelit::editor
