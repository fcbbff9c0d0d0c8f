#include "viewport/move_gizmo.h"

#include "viewport/scene_picker.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace wavelit::editor {
namespace {

const std::array<glm::vec3, 3> kAxes = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

bool isSun(const scene::Scene& scene, EntityRef ref) {
    if (ref.kind != EntityKind::Light) return false;
    for (const auto& light : scene.lighting.lights)
        if (light.id == ref.id) return light.type == scene::LightType::Sun;
    return false;
}

} // namespace

std::optional<GizmoGeometry> gizmoGeometry(const scene::Scene& scene, EntityRef ref, const ViewProjection& view,
                                           float pxScale) {
    const float axisLength = kAxisLengthPx * pxScale;
    const auto world = handlePosition(scene, ref);
    if (!world) return std::nullopt;
    const auto centre = view.project(*world);
    if (!centre) return std::nullopt;
    GizmoGeometry g;
    g.centre = *centre;
    g.sun = isSun(scene, ref);
    if (g.sun) return g;
    // Axis arrows of a fixed screen length: project a short world step and scale it.
    const float step = view.worldPerPixel(std::max(view.depth(*world), 1e-3f)) * axisLength;
    for (int a = 0; a < 3; ++a) {
        const auto tip = view.project(*world + kAxes[size_t(a)] * step);
        if (!tip || glm::length(*tip - *centre) < 0.15f * axisLength) continue; // end-on: unusable
        g.axisTips[size_t(a)] = *centre + glm::normalize(*tip - *centre) * axisLength;
    }
    return g;
}

GizmoPart hitGizmo(const GizmoGeometry& gizmo, glm::vec2 pixel, float pxScale) {
    if (glm::length(pixel - gizmo.centre) <= (kGizmoGrabPx + 3.0f) * pxScale)
        return gizmo.sun ? GizmoPart::SunSphere : GizmoPart::Centre;
    if (gizmo.sun) return GizmoPart::None;
    GizmoPart best = GizmoPart::None;
    float bestDistance = kGizmoGrabPx * pxScale;
    for (int a = 0; a < 3; ++a) {
        const auto& tip = gizmo.axisTips[size_t(a)];
        if (!tip) continue;
        const float d = distanceToSegment(pixel, gizmo.centre, *tip);
        if (d <= bestDistance) {
            bestDistance = d;
            best = GizmoPart(int(GizmoPart::AxisX) + a);
        }
    }
    return best;
}

GizmoDrag::GizmoDrag(GizmoPart part, const scene::Scene& scene, EntityRef ref, const ViewProjection& view,
                     glm::vec2 pressPixel)
    : m_part(part), m_entity(ref), m_view(view) {
    const auto world = handlePosition(scene, ref);
    if (!world || part == GizmoPart::None) return;
    m_start = *world;
    if (part == GizmoPart::SunSphere) {
        m_sunCentre = scene.camera.target;
        m_sunRadius = std::max(sunHandleDistance(scene.camera), 1e-3f);
        m_valid = true;
        return;
    }
    const glm::vec3 toCamera = glm::normalize(view.position() - m_start);
    if (part == GizmoPart::Centre) {
        m_planeNormal = view.forward();
    } else {
        m_axis = kAxes[size_t(int(part) - int(GizmoPart::AxisX))];
        // The plane through the axis that faces the camera best.
        const glm::vec3 side = glm::cross(m_axis, toCamera);
        if (glm::length(side) < 1e-4f) return;
        m_planeNormal = glm::normalize(glm::cross(side, m_axis));
    }
    const auto press = intersectPlane(view.ray(pressPixel), m_start, m_planeNormal);
    if (!press) return;
    m_pressPoint = *press;
    m_valid = true;
}

std::optional<glm::vec3> GizmoDrag::onDragPlane(glm::vec2 pixel) const {
    return intersectPlane(m_view.ray(pixel), m_start, m_planeNormal);
}

glm::vec3 GizmoDrag::positionAt(glm::vec2 pixel) const {
    if (!m_valid || m_part == GizmoPart::SunSphere) return m_start;
    const auto hit = onDragPlane(pixel);
    if (!hit) return m_start; // the mouse left the plane's visible half: stay put
    const glm::vec3 delta = *hit - m_pressPoint;
    if (m_part == GizmoPart::Centre) return m_start + delta;
    return m_start + m_axis * glm::dot(delta, m_axis);
}

glm::vec3 GizmoDrag::sunDirectionAt(glm::vec2 pixel) const {
    const ViewRay ray = m_view.ray(pixel);
    // The ray's first hit on the handle sphere; a ray that misses takes the sphere point nearest to it.
    const glm::vec3 oc = ray.origin - m_sunCentre;
    const float b = glm::dot(oc, ray.direction);
    const float c = glm::dot(oc, oc) - m_sunRadius * m_sunRadius;
    const float disc = b * b - c;
    glm::vec3 onSphere;
    if (disc >= 0.0f) {
        float t = -b - std::sqrt(disc);
        if (t < 0.0f) t = -b + std::sqrt(disc);
        onSphere = ray.origin + std::max(t, 0.0f) * ray.direction;
    } else {
        const glm::vec3 closest = ray.origin - b * ray.direction;
        onSphere = m_sunCentre + glm::normalize(closest - m_sunCentre) * m_sunRadius;
    }
    const glm::vec3 toTarget = m_sunCentre - onSphere;
    return glm::length(toTarget) > 0.0f ? glm::normalize(toTarget) : glm::normalize(m_sunCentre - m_start);
}

} // namespace wavelit::editor
