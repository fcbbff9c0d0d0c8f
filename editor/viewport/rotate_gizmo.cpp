#include "viewport/rotate_gizmo.h"

#include "viewport/scene_picker.h"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wavelit::editor {
namespace {

const std::array<glm::vec3, 3> kAxes = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};

// Two unit vectors spanning the plane normal to `axis`, with e1 x e2 = axis.
std::pair<glm::vec3, glm::vec3> ringBasis(int axis) {
    const glm::vec3& a = kAxes[size_t(axis)];
    const glm::vec3 e1 = kAxes[size_t((axis + 1) % 3)];
    return {e1, glm::cross(a, e1)};
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

glm::vec3 rotateAbout(const glm::vec3& v, const glm::vec3& axis, float angle) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), angle, axis) * glm::vec4(v, 0.0f));
}

} // namespace

bool rotatable(const scene::Scene& scene, EntityRef ref) {
    if (ref.kind == EntityKind::Object) return scene.findObject(ref.id) != nullptr;
    if (ref.kind != EntityKind::Light) return false;
    const scene::Light* light = scene.findLight(ref.id);
    return light && (light->type == scene::LightType::Spot || light->type == scene::LightType::Rect ||
                     light->type == scene::LightType::Sun);
}

std::optional<RotateGeometry> rotateGeometry(const scene::Scene& scene, EntityRef ref, const ViewProjection& view,
                                             float pxScale) {
    if (!rotatable(scene, ref)) return std::nullopt;
    const auto world = handlePosition(scene, ref);
    if (!world) return std::nullopt;
    const auto centre = view.project(*world);
    if (!centre) return std::nullopt;
    RotateGeometry g;
    g.centre = *centre;
    g.ringRadiusImagePx = kRingRadiusPx * pxScale;
    const float radius = view.worldPerPixel(std::max(view.depth(*world), 1e-3f)) * g.ringRadiusImagePx;
    for (int axis = 0; axis < 3; ++axis) {
        const auto [e1, e2] = ringBasis(axis);
        RotateRing ring;
        ring.axis = axis;
        float best = -1.0f;
        bool complete = true;
        for (int i = 0; i < kRingSegments && complete; ++i) {
            const float t = 2.0f * std::numbers::pi_v<float> * float(i) / float(kRingSegments);
            const glm::vec3 offset = std::cos(t) * e1 + std::sin(t) * e2;
            const glm::vec3 tangent = -std::sin(t) * e1 + std::cos(t) * e2; // increasing angle
            const auto p = view.project(*world + radius * offset);
            const auto q = view.project(*world + radius * offset + 0.05f * radius * tangent);
            if (!p || !q) complete = false;
            else {
                const glm::vec2 d = *q - *p;
                const float len = glm::length(d);
                ring.points.push_back(*p);
                ring.tangents.push_back(len > 1e-6f ? d / len : glm::vec2(0.0f));
                // Grab candidates sit halfway between the world axes: each ring crosses the other
                // two on the axes, where a grab would be ambiguous.
                if (i % (kRingSegments / 4) == kRingSegments / 8 && len > best) {
                    best = len;
                    ring.grabIndex = size_t(i);
                }
            }
        }
        if (complete) g.rings.push_back(std::move(ring));
    }
    if (g.rings.empty()) return std::nullopt;
    return g;
}

std::optional<std::pair<int, size_t>> hitRotateRing(const RotateGeometry& gizmo, glm::vec2 pixel, float pxScale) {
    std::optional<std::pair<int, size_t>> best;
    float bestDistance = 7.0f * pxScale; // kGizmoGrabPx (move_gizmo.h)
    for (size_t r = 0; r < gizmo.rings.size(); ++r) {
        const auto& pts = gizmo.rings[r].points;
        for (size_t i = 0; i < pts.size(); ++i) {
            const float d = distanceToSegment(pixel, pts[i], pts[(i + 1) % pts.size()]);
            if (d > bestDistance) continue;
            bestDistance = d;
            // The nearer end of the segment names the grabbed point (its tangent).
            const size_t nearest =
                glm::length(pixel - pts[i]) <= glm::length(pixel - pts[(i + 1) % pts.size()]) ? i : (i + 1) % pts.size();
            best = std::make_pair(int(r), nearest);
        }
    }
    return best;
}

RotateDrag::RotateDrag(const scene::Scene& scene, EntityRef ref, const RotateGeometry& gizmo, int ringIndex,
                       size_t pointIndex, glm::vec2 pressPixel)
    : m_entity(ref), m_press(pressPixel), m_radiusPx(std::max(gizmo.ringRadiusImagePx, 1e-3f)) {
    if (ringIndex < 0 || size_t(ringIndex) >= gizmo.rings.size()) return;
    const RotateRing& ring = gizmo.rings[size_t(ringIndex)];
    if (pointIndex >= ring.tangents.size()) return;
    m_axis = kAxes[size_t(ring.axis)];
    m_tangent = ring.tangents[pointIndex];
    if (glm::length(m_tangent) < 0.5f) return; // grabbed where the ring runs toward the camera
    if (ref.kind == EntityKind::Light) {
        const scene::Light* light = scene.findLight(ref.id);
        if (!light || glm::length(light->direction) <= 0.0f) return;
        m_startDirection = glm::normalize(light->direction);
    } else {
        const scene::Object* object = scene.findObject(ref.id);
        if (!object) return;
        m_startRotationDeg = object->transform.rotationDeg;
    }
    m_valid = true;
}

float RotateDrag::angleAt(glm::vec2 pixel) const {
    return m_valid ? glm::dot(pixel - m_press, m_tangent) / m_radiusPx : 0.0f;
}

glm::vec3 RotateDrag::valueAt(glm::vec2 pixel) const {
    const float angle = angleAt(pixel);
    if (m_entity.kind == EntityKind::Light) return glm::normalize(rotateAbout(m_startDirection, m_axis, angle));
    return rotateEulerDeg(m_startRotationDeg, m_axis, angle);
}

glm::vec3 rotateEulerDeg(const glm::vec3& startDeg, const glm::vec3& axis, float angle) {
    const glm::vec3 r = glm::radians(startDeg);
    const glm::mat4 start = glm::eulerAngleZYX(r.z, r.y, r.x); // Rz Ry Rx, as Transform::matrix
    const glm::mat4 turned = glm::rotate(glm::mat4(1.0f), angle, axis) * start;
    float z = 0.0f, y = 0.0f, x = 0.0f;
    glm::extractEulerAngleZYX(turned, z, y, x);
    return glm::degrees(glm::vec3(x, y, z));
}

} // namespace wavelit::editor
