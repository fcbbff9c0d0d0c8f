#include "scene/scene_validation.h"

#include <glm/geometric.hpp>

#include <map>
#include <set>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

// Ids are unique per kind (EntityRef and Invalidation carry the kind); names likewise, empty
// names excepted.
template <typename E>
util::Status checkUnique(const std::vector<E>& items, const std::string& file, const std::string& section,
                         const char* kindName) {
    std::map<EntityId, size_t> ids;
    std::map<std::string, size_t> names;
    for (size_t i = 0; i < items.size(); ++i) {
        const std::string where = section + "/" + std::to_string(i);
        if (items[i].id == kInvalidId) return makeError(ErrorKind::Invalid, file, std::string(kindName) + " has no id", where + "/id");
        if (auto [it, fresh] = ids.emplace(items[i].id, i); !fresh)
            return makeError(ErrorKind::Invalid, file,
                             "duplicate " + std::string(kindName) + " id " + std::to_string(items[i].id) +
                                 " (also at " + section + "/" + std::to_string(it->second) + ")",
                             where + "/id");
        if (items[i].name.empty()) continue;
        if (auto [it, fresh] = names.emplace(items[i].name, i); !fresh)
            return makeError(ErrorKind::Invalid, file,
                             "duplicate " + std::string(kindName) + " name '" + items[i].name + "' (also at " +
                                 section + "/" + std::to_string(it->second) + ")",
                             where + "/name");
    }
    return util::okStatus();
}

// Below this a direction vector has no direction (normalising it would amplify round-off).
constexpr float kMinDirectionLength = 1e-6f;

} // namespace

util::Status validateLighting(const LightingSetup& lighting, const std::string& file, const std::string& prefix) {
    if (auto s = checkUnique(lighting.lights, file, prefix + "/lights", "light"); !s) return s;
    for (size_t i = 0; i < lighting.lights.size(); ++i) {
        const Light& l = lighting.lights[i];
        const std::string where = prefix + "/lights/" + std::to_string(i);
        const bool directed = l.type == LightType::Spot || l.type == LightType::Sun || l.type == LightType::Rect;
        if (directed && glm::length(l.direction) < kMinDirectionLength)
            return makeError(ErrorKind::Invalid, file, "light '" + l.name + "' has a zero direction", where + "/direction");
        if (l.type == LightType::Spot && l.coneInnerDeg > l.coneOuterDeg)
            return makeError(ErrorKind::Invalid, file,
                             "light '" + l.name + "': inner cone angle exceeds the outer one", where + "/coneInner");
    }
    return util::okStatus();
}

util::Status validateScene(const Scene& scene, const std::string& file) {
    if (glm::length(scene.camera.target - scene.camera.position) < kMinDirectionLength)
        return makeError(ErrorKind::Invalid, file, "camera target equals its position", "/camera/target");
    if (auto s = checkUnique(scene.materials, file, "/materials", "material"); !s) return s;
    if (auto s = checkUnique(scene.objects, file, "/objects", "object"); !s) return s;
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (!scene.findMaterial(scene.objects[i].materialId))
            return makeError(ErrorKind::NotFound, file,
                             "object '" + scene.objects[i].name + "' uses material " +
                                 std::to_string(scene.objects[i].materialId) + ", which does not exist",
                             "/objects/" + std::to_string(i) + "/material");
    // A referenced lighting setup was validated against its own file when it was loaded.
    if (!scene.lightingPath.empty()) return util::okStatus();
    return validateLighting(scene.lighting, file, "/lighting");
}

} // namespace wavelit::scene
