// ScenePicker: which entity is under an image point of the viewport. Light handles come first
// (a light is a point or a small shape the artist grabs by its handle, drawn by the gizmo
// overlay), then the closest object hit by the camera ray through the point (a CPU BVH of the
// scene, built on the first pick after the objects changed: a few ms for the bundled scenes;
// never during a drag, which only re-projects handles). Environment and camera have no handle.
#pragma once

#include "panels/entity_ref.h"
#include "viewport/view_projection.h"

#include "scene/bvh.h"
#include "scene/scene.h"

#include <memory>
#include <optional>

namespace wavelit::editor {

inline constexpr float kHandlePickRadiusPx = 10.0f; // screen pixels round a handle that grab it

// Where an entity's handle is in world space: a light's position (a sun, which has only a
// direction, sits on a sphere round the camera target: target - direction * sunHandleDistance),
// an object's translation. Nullopt for entities without a handle.
std::optional<glm::vec3> handlePosition(const scene::Scene& scene, EntityRef ref);
// The radius of the sun handle's sphere round the camera target: 0.6 of the target distance, so
// the handle is in view whenever the sun is above the camera's horizon.
float sunHandleDistance(const scene::Camera& camera);

class ScenePicker {
public:
    // The light whose handle is within kHandlePickRadiusPx of `pixel`, else the object hit first
    // along the ray, else nullopt (the environment). `pxScale`: image pixels per screen pixel.
    std::optional<EntityRef> pick(std::shared_ptr<const scene::Scene> scene, int imageWidth,
                                  int imageHeight, glm::vec2 pixel, float pxScale);
    std::optional<EntityRef> pickLightHandle(const scene::Scene& scene, const ViewProjection& view,
                                             glm::vec2 pixel, float pxScale) const;
    std::optional<EntityRef> pickObject(std::shared_ptr<const scene::Scene> scene, const ViewProjection& view,
                                        glm::vec2 pixel);

private:
    const scene::Bvh& bvhFor(std::shared_ptr<const scene::Scene> scene);
    std::shared_ptr<const scene::Scene> m_bvhScene; // the scene m_bvh was built from
    scene::Bvh m_bvh;
};

} // namespace wavelit::editor
