#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace wavelit::scene {

glm::mat4 Transform::matrix() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
    m = glm::rotate(m, glm::radians(rotationDeg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotationDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotationDeg.x), glm::vec3(1, 0, 0));
    return glm::scale(m, scale);
}

namespace {
template <typename T> const T* findById(const std::vector<T>& items, EntityId id) {
    auto it = std::find_if(items.begin(), items.end(), [id](const T& t) { return t.id == id; });
    return it == items.end() ? nullptr : &*it;
}
} // namespace

plugins::BrdfParams brdfParamsOf(const Material& m) {
    return plugins::BrdfParams(m.baseColor, m.roughness, m.anisotropy, m.brdfTable);
}

const Material* Scene::findMaterial(EntityId id) const { return findById(materials, id); }
const Object* Scene::findObject(EntityId id) const { return findById(objects, id); }
const Light* Scene::findLight(EntityId id) const { return findById(lighting.lights, id); }

EntityId Scene::nextId() const {
    EntityId top = 0;
    for (const auto& m : materials) top = std::max(top, m.id);
    for (const auto& o : objects) top = std::max(top, o.id);
    for (const auto& l : lighting.lights) top = std::max(top, l.id);
    return top + 1;
}

} // namespace wavelit::scene
