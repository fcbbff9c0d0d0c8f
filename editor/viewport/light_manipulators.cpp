#include "viewport/light_manipulators.h"

#include "viewport/move_gizmo.h"

#include "scene/property_registry.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace wavelit::editor {
namespace {

constexpr int kOutlineSegments = 32;
constexpr float kMaxDrawnConeDeg = 85.0f; // a wider rim would be drawn far off screen

// The rect's axes as the tracers build them (light_sampler.h "Rect").
std::pair<glm::vec3, glm::vec3> rectAxes(const glm::vec3& direction) {
    const glm::vec3 n = glm::normalize(direction);
    const glm::vec3 ref = std::abs(n.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(ref, n));
    return {u, glm::cross(n, u)};
}

// A vector perpendicular to `axis` that shows on screen: the view's right (else up) made
// perpendicular.
glm::vec3 screenPerpendicular(const glm::vec3& axis, const ViewProjection& view) {
    for (const glm::vec3& candidate : {view.right(), view.up()}) {
        const glm::vec3 p = candidate - glm::dot(candidate, axis) * axis;
        if (glm::length(p) > 1e-3f) return glm::normalize(p);
    }
    return view.right();
}

std::string format(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", double(v));
    return text;
}

} // namespace

const char* manipulatorName(ManipulatorKind kind) {
    switch (kind) {
    case ManipulatorKind::Radius: return "radius";
    case ManipulatorKind::SizeX: return "sizeX";
    case ManipulatorKind::SizeY: return "sizeY";
    case ManipulatorKind::Cone: return "cone";
    }
    return "";
}

std::optional<ManipulatorGeometry> manipulatorGeometry(const scene::Scene& scene, EntityRef ref,
                                                       const ViewProjection& view, float pxScale) {
    if (ref.kind != EntityKind::Light) return std::nullopt;
    const scene::Light* light = scene.findLight(ref.id);
    if (!light) return std::nullopt;
    const glm::vec3 c = light->position;
    const auto centre = view.project(c);
    if (!centre) return std::nullopt;
    ManipulatorGeometry g;
    auto outline = [&](auto&& pointAt) {
        std::vector<glm::vec2> pts;
        for (int i = 0; i < kOutlineSegments; ++i) {
            const auto p = view.project(pointAt(2.0f * std::numbers::pi_v<float> * float(i) / kOutlineSegments));
            if (!p) return;
            pts.push_back(*p);
        }
        g.outlines.push_back(std::move(pts));
    };
    // A handle drawn at least kMinHandlePx from its anchor, along its own screen direction.
    auto handle = [&](ManipulatorKind kind, const glm::vec3& world, glm::vec2 anchor, const glm::vec3& outward) {
        const auto p = view.project(world);
        if (!p) return;
        glm::vec2 dir = *p - anchor;
        if (glm::length(dir) < 1e-4f) {
            const auto q = view.project(world + outward * view.worldPerPixel(std::max(view.depth(world), 1e-3f)));
            dir = q ? *q - anchor : glm::vec2(1, 1);
        }
        dir = glm::length(dir) > 1e-6f ? glm::normalize(dir) : glm::vec2(1, 0);
        const float minPx = kMinHandlePx * pxScale;
        const glm::vec2 pixel = glm::length(*p - anchor) < minPx ? anchor + dir * minPx : *p;
        g.handles.push_back({kind, world, pixel, anchor});
    };
    switch (light->type) {
    case scene::LightType::Sphere: {
        const glm::vec3 outward = glm::normalize(view.right() - view.up());
        outline([&](float t) { return c + light->radius * (std::cos(t) * view.right() + std::sin(t) * view.up()); });
        handle(ManipulatorKind::Radius, c + light->radius * outward, *centre, outward);
        break;
    }
    case scene::LightType::Rect: {
        if (glm::length(light->direction) <= 0.0f) return std::nullopt;
        const auto [u, v] = rectAxes(light->direction);
        const glm::vec3 hu = 0.5f * light->size.x * u, hv = 0.5f * light->size.y * v;
        std::vector<glm::vec2> corners;
        for (const glm::vec3& corner : {c - hu - hv, c + hu - hv, c + hu + hv, c - hu + hv})
            if (auto p = view.project(corner)) corners.push_back(*p);
        if (corners.size() == 4) g.outlines.push_back(std::move(corners));
        handle(ManipulatorKind::SizeX, c + hu, *centre, u);
        handle(ManipulatorKind::SizeY, c + hv, *centre, v);
        break;
    }
    case scene::LightType::Spot: {
        if (glm::length(light->direction) <= 0.0f) return std::nullopt;
        const glm::vec3 axis = glm::normalize(light->direction);
        const glm::vec3 perp = screenPerpendicular(axis, view);
        const glm::vec3 side = glm::cross(axis, perp);
        const float d = view.worldPerPixel(std::max(view.depth(c), 1e-3f)) * kConeHandleDepthPx * pxScale;
        const float rim = d * std::tan(glm::radians(std::min(light->coneOuterDeg, kMaxDrawnConeDeg)));
        const glm::vec3 base = c + d * axis;
        outline([&](float t) { return base + rim * (std::cos(t) * perp + std::sin(t) * side); });
        for (float s : {1.0f, -1.0f}) {
            const auto p = view.project(base + s * rim * perp);
            if (p) g.lines.emplace_back(*centre, *p);
        }
        handle(ManipulatorKind::Cone, base + rim * perp, *centre, perp);
        break;
    }
    default: return std::nullopt;
    }
    if (g.handles.empty()) return std::nullopt;
    return g;
}

std::optional<ManipulatorHandle> hitManipulator(const ManipulatorGeometry& g, glm::vec2 pixel, float pxScale) {
    std::optional<ManipulatorHandle> best;
    float bestDistance = kGizmoGrabPx * pxScale;
    for (const auto& h : g.handles) {
        const float d = glm::length(pixel - h.pixel);
        if (d <= bestDistance) {
            bestDistance = d;
            best = h;
        }
    }
    return best;
}

ManipulatorDrag::ManipulatorDrag(const scene::Scene& scene, EntityRef ref, const ManipulatorHandle& handle,
                                 const ViewProjection& view, glm::vec2 pressPixel)
    : m_entity(ref), m_kind(handle.kind), m_view(view) {
    const scene::Light* light = scene.findLight(ref.id);
    if (!light) return;
    m_centre = light->position;
    const char* property = m_kind == ManipulatorKind::Radius ? "radius"
                           : m_kind == ManipulatorKind::Cone ? "coneOuter"
                                                             : "size";
    const scene::PropertyInfo* info = scene::findProperty(EntityKind::Light, property);
    if (!info) return;
    m_lo = float(info->min);
    m_hi = float(info->max);
    // The drag plane: through the handle, facing the camera (a rect: its own plane unless seen
    // nearly edge-on).
    m_planePoint = handle.world;
    m_planeNormal = view.forward();
    switch (m_kind) {
    case ManipulatorKind::Radius:
        m_outward = glm::normalize(view.right() - view.up());
        m_start = light->radius;
        break;
    case ManipulatorKind::SizeX:
    case ManipulatorKind::SizeY: {
        const auto [u, v] = rectAxes(light->direction);
        m_outward = m_kind == ManipulatorKind::SizeX ? u : v;
        m_startSize = light->size;
        m_start = m_kind == ManipulatorKind::SizeX ? light->size.x : light->size.y;
        m_lo = std::max(m_lo, kMinRectSize);
        const glm::vec3 n = glm::normalize(light->direction);
        if (std::abs(glm::dot(view.ray(pressPixel).direction, n)) > 0.25f) m_planeNormal = n;
        break;
    }
    case ManipulatorKind::Cone:
        m_axis = glm::normalize(light->direction);
        m_outward = screenPerpendicular(m_axis, view); // the side the handle is drawn on
        m_start = light->coneOuterDeg;
        m_lo = std::max(m_lo, light->coneInnerDeg); // inner <= outer (scene_validation.cpp)
        break;
    }
    const auto press = onPlane(pressPixel);
    if (!press) return;
    m_pressPoint = *press;
    m_valid = true;
}

std::optional<glm::vec3> ManipulatorDrag::onPlane(glm::vec2 pixel) const {
    return intersectPlane(m_view.ray(pixel), m_planePoint, m_planeNormal);
}

float ManipulatorDrag::coneAngleDeg(const glm::vec3& p) const {
    // Signed toward the handle's side: a drag across the axis narrows the cone below 0, not
    // back open on the other side.
    const glm::vec3 w = p - m_centre;
    return glm::degrees(std::atan2(glm::dot(w, m_outward), glm::dot(w, m_axis)));
}

ManipulatorValue ManipulatorDrag::valueAt(glm::vec2 pixel) const {
    const auto hit = onPlane(pixel);
    float wanted = m_start;
    if (m_valid && hit) {
        if (m_kind == ManipulatorKind::Cone)
            wanted = m_start + coneAngleDeg(*hit) - coneAngleDeg(m_pressPoint);
        else {
            // The handle sits at the edge's middle: the full width grows by twice its travel.
            const float travel = glm::dot(*hit - m_pressPoint, m_outward);
            wanted = m_start + (m_kind == ManipulatorKind::Radius ? 1.0f : 2.0f) * travel;
        }
    }
    const float held = std::clamp(wanted, m_lo, m_hi);
    ManipulatorValue out;
    if (held != wanted) {
        const char* label = m_kind == ManipulatorKind::Radius ? "Radius"
                            : m_kind == ManipulatorKind::Cone ? "Cone outer"
                            : m_kind == ManipulatorKind::SizeX ? "Width"
                                                               : "Height";
        const char* unit = m_kind == ManipulatorKind::Cone ? "°" : " m";
        // Built by appends: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
        std::string& m = out.clamped;
        m.append(label).append(": ").append(format(wanted)).append(unit).append(" is outside [");
        m.append(format(m_lo)).append(", ").append(m_hi >= 1e29f ? std::string("∞)") : format(m_hi).append("]"));
        m.append(" — held at ").append(format(held)).append(unit);
    }
    switch (m_kind) {
    case ManipulatorKind::Radius: out.property = "radius"; out.value = held; break;
    case ManipulatorKind::Cone: out.property = "coneOuter"; out.value = held; break;
    case ManipulatorKind::SizeX: out.property = "size"; out.value = glm::vec2(held, m_startSize.y); break;
    case ManipulatorKind::SizeY: out.property = "size"; out.value = glm::vec2(m_startSize.x, held); break;
    }
    return out;
}

} // namespace wavelit::editor
