#include "viewport/scene_picker.h"

#include <glm/geometric.hpp>

#include <limits>

namespace wavelit::editor {
namespace {

// The BVH holds world-space triangles: it stays valid while no object's mesh or transform moved.
bool sameGeometry(const scene::Scene& a, const scene::Scene& b) {
    if (a.objects.size() != b.objects.size()) return false;
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const auto& x = a.objects[i];
        const auto& y = b.objects[i];
        if (x.id != y.id || x.mesh != y.mesh || x.transform.translation != y.transform.translation ||
            x.transform.rotationDeg != y.transform.rotationDeg || x.transform.scale != y.transform.scale)
            return false;
    }
    return true;
}

} // namespace

float sunHandleDistance(const scene::Camera& camera) {
    return 0.6f * glm::length(camera.position - camera.target);
}

std::optional<glm::vec3> handlePosition(const scene::Scene& scene, EntityRef ref) {
    if (ref.kind == EntityKind::Light) {
        for (const auto& light : scene.lighting.lights) {
            if (light.id != ref.id) continue;
            if (light.type == scene::LightType::Sun)
                return scene.camera.target - glm::normalize(light.direction) * sunHandleDistance(scene.camera);
            return light.position;
        }
    } else if (ref.kind == EntityKind::Object) {
        for (const auto& object : scene.objects)
            if (object.id == ref.id) return object.transform.translation;
    }
    return std::nullopt;
}

std::optional<EntityRef> ScenePicker::pick(std::shared_ptr<const scene::Scene> scene, int imageWidth,
                                           int imageHeight, glm::vec2 pixel, float pxScale) {
    if (!scene) return std::nullopt;
    const ViewProjection view(scene->camera, imageWidth, imageHeight);
    if (auto light = pickLightHandle(*scene, view, pixel, pxScale)) return light;
    return pickObject(std::move(scene), view, pixel);
}

std::optional<EntityRef> ScenePicker::pickLightHandle(const scene::Scene& scene, const ViewProjection& view,
                                                      glm::vec2 pixel, float pxScale) const {
    std::optional<EntityRef> best;
    float bestDistance = kHandlePickRadiusPx * pxScale;
    for (const auto& light : scene.lighting.lights) {
        const EntityRef ref{EntityKind::Light, light.id};
        const auto world = handlePosition(scene, ref);
        const auto projected = world ? view.project(*world) : std::nullopt;
        if (!projected) continue;
        const float distance = glm::length(*projected - pixel);
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = ref;
        }
    }
    return best;
}

std::optional<EntityRef> ScenePicker::pickObject(std::shared_ptr<const scene::Scene> scene,
                                                 const ViewProjection& view, glm::vec2 pixel) {
    const scene::Bvh& bvh = bvhFor(scene);
    const ViewRay ray = view.ray(pixel);
    scene::BvhHit hit;
    if (!scene::intersect(bvh, ray.origin, ray.direction, 0.0f, std::numeric_limits<float>::max(), hit))
        return std::nullopt;
    const auto objectIndex = size_t(bvh.triangles[hit.triangle].v1[3]); // bvh.h: w of v1
    if (objectIndex >= scene->objects.size()) return std::nullopt;
    return EntityRef{EntityKind::Object, scene->objects[objectIndex].id};
}

const scene::Bvh& ScenePicker::bvhFor(std::shared_ptr<const scene::Scene> scene) {
    if (!m_bvhScene || (m_bvhScene != scene && !sameGeometry(*m_bvhScene, *scene))) {
        m_bvh = scene::buildBvh(*scene);
    }
    m_bvhScene = std::move(scene);
    return m_bvh;
}

} // namespace wavelit::editor
