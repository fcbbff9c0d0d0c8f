// LightManipulators: the selected light's shape handles in the viewport, as geometry in image
// pixels and the drag that edits one property (both gizmo modes show them):
//   sphere  "radius"      a handle on the sphere's outline (screen down-right of the centre);
//   rect    "sizeX"/"sizeY" a handle at the middle of a width edge and of a height edge
//                           (axes as the tracers': light_sampler.h, U = normalize(ref x n));
//   spot    "cone"        a handle on the outer cone's rim, kConeHandleDepthPx (on screen, at the
//                           light's depth) along the light's direction; edits coneOuter.
// A point light has no size (the registry's `radius` is the sphere's), a sun's angular diameter
// is a panel value: no handles. A handle closer to the centre than kMinHandlePx is drawn pushed out
// to that distance, so it is never under the move gizmo's centre square; drags are relative (the
// value changes by the mouse's travel, not to where the mouse is), so the push changes nothing.
// Values are clamped to the registry's range (property_registry.cpp; a rect no smaller than
// kMinRectSize, whose zero area would have no radiance; the outer cone no narrower than the inner
// one, as scene_validation.cpp requires), and a clamped drag says so (ManipulatorValue::clamped).
// No Qt.
#pragma once

#include "panels/entity_ref.h"
#include "viewport/view_projection.h"

#include "scene/property_value.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace wavelit::editor {

inline constexpr float kMinHandlePx = 18.0f;       // screen pixels from the light's centre
inline constexpr float kConeHandleDepthPx = 60.0f; // screen pixels along a spot's axis
inline constexpr float kMinRectSize = 1e-3f;       // m

enum class ManipulatorKind { Radius, SizeX, SizeY, Cone };
const char* manipulatorName(ManipulatorKind kind); // "radius", "sizeX", "sizeY", "cone"

struct ManipulatorHandle {
    ManipulatorKind kind = ManipulatorKind::Radius;
    glm::vec3 world{0.0f};  // where it is drawn (pushed out when too close to the centre)
    glm::vec2 pixel{0.0f};
    glm::vec2 anchor{0.0f}; // the light's centre (radius, size) or the cone's apex, for the line to it
};

struct ManipulatorGeometry {
    std::vector<ManipulatorHandle> handles;
    std::vector<std::vector<glm::vec2>> outlines; // closed polylines: sphere outline, rect, cone rim
    std::vector<std::pair<glm::vec2, glm::vec2>> lines; // cone sides
};

// The handles of `ref` (a sphere, rect or spot light) as drawn; nullopt for none.
std::optional<ManipulatorGeometry> manipulatorGeometry(const scene::Scene& scene, EntityRef ref,
                                                       const ViewProjection& view, float pxScale);
// The handle under `pixel` (within kGizmoGrabPx, move_gizmo.h).
std::optional<ManipulatorHandle> hitManipulator(const ManipulatorGeometry& g, glm::vec2 pixel, float pxScale);

struct ManipulatorValue {
    std::string property;  // "radius", "size", "coneOuter"
    scene::PropertyValue value;
    std::string clamped;   // empty, or "Cone outer: 95° is outside [20, 90] — held at 90°"
};

class ManipulatorDrag {
public:
    ManipulatorDrag(const scene::Scene& scene, EntityRef ref, const ManipulatorHandle& handle,
                    const ViewProjection& view, glm::vec2 pressPixel);
    bool valid() const { return m_valid; }
    EntityRef entity() const { return m_entity; }
    ManipulatorKind kind() const { return m_kind; }
    ManipulatorValue valueAt(glm::vec2 pixel) const;

private:
    std::optional<glm::vec3> onPlane(glm::vec2 pixel) const;
    float coneAngleDeg(const glm::vec3& p) const;
    EntityRef m_entity;
    ManipulatorKind m_kind = ManipulatorKind::Radius;
    ViewProjection m_view;
    glm::vec3 m_planePoint{0.0f}, m_planeNormal{0.0f};
    glm::vec3 m_pressPoint{0.0f};
    glm::vec3 m_centre{0.0f}, m_outward{0.0f}, m_axis{0.0f};
    float m_start = 0.0f;     // radius, width, height or outer cone angle at the press
    glm::vec2 m_startSize{0.0f};
    float m_lo = 0.0f, m_hi = 0.0f; // the allowed range
    bool m_valid = false;
};

} // namespace wavelit::editor
