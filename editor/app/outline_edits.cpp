#include "app/outline_edits.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>

namespace wavelit::editor {
namespace {

using util::ErrorKind;
using util::makeError;

constexpr std::array<const char*, 5> kLightTypes = {"point", "sphere", "rect", "spot", "sun"};
constexpr std::array<const char*, 5> kLightLabels = {"Point light", "Sphere light", "Rect light",
                                                     "Spot light", "Sun"};

template <typename E> bool nameTaken(const std::vector<E>& list, const std::string& name) {
    return std::any_of(list.begin(), list.end(), [&](const E& e) { return e.name == name; });
}

bool nameTaken(const scene::Scene& scene, EntityKind kind, const std::string& name) {
    switch (kind) {
    case EntityKind::Light: return nameTaken(scene.lighting.lights, name);
    case EntityKind::Object: return nameTaken(scene.objects, name);
    case EntityKind::Material: return nameTaken(scene.materials, name);
    default: return false;
    }
}

// `wanted` if given (an error if taken), else the first free "<base> N" / "<base>".
util::Result<std::string> pickName(const scene::Scene& scene, EntityKind kind, const std::string& wanted,
                                   const std::string& base, bool numberFirst) {
    if (!wanted.empty()) {
        if (nameTaken(scene, kind, wanted))
            return makeError(ErrorKind::Invalid, "",
                             std::string("a ") + scene::entityKindName(kind) + " named '" + wanted +
                                 "' already exists");
        return wanted;
    }
    if (!numberFirst && !nameTaken(scene, kind, base)) return base;
    for (int n = numberFirst ? 1 : 2;; ++n) {
        std::string candidate = base;
        candidate += ' ';
        candidate += std::to_string(n);
        if (!nameTaken(scene, kind, candidate)) return candidate;
    }
}

} // namespace

std::optional<scene::LightType> parseLightType(const std::string& text) {
    for (size_t i = 0; i < kLightTypes.size(); ++i)
        if (text == kLightTypes[i]) return scene::LightType(i);
    return std::nullopt;
}

util::Result<scene::ChangeSet> addLightChange(const scene::Scene& scene, scene::LightType type,
                                              const std::string& name) {
    auto picked = pickName(scene, EntityKind::Light, name, kLightLabels[size_t(type)], true);
    if (!picked) return picked.error();
    scene::Light light;
    light.id = scene.nextId();
    light.name = *picked;
    light.type = type;
    switch (type) {
    case scene::LightType::Point: break;
    case scene::LightType::Sphere: light.radius = 0.1f; break;
    case scene::LightType::Rect:
        light.position = {0.0f, 2.0f, 0.0f};
        light.size = {0.5f, 0.5f};
        break;
    case scene::LightType::Spot:
        light.position = {0.0f, 3.0f, 1.0f};
        light.direction = glm::normalize(glm::vec3(0.0f, -3.0f, -1.0f));
        break;
    case scene::LightType::Sun:
        light.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
        light.intensity = 3.0f;
        break;
    }
    scene::ChangeSet changes;
    changes.addLight(scene, std::move(light));
    return changes;
}

util::Result<scene::ChangeSet> addMaterialChange(const scene::Scene& scene, const std::string& name) {
    auto picked = pickName(scene, EntityKind::Material, name, "Material", true);
    if (!picked) return picked.error();
    scene::Material material;
    material.id = scene.nextId();
    material.name = *picked;
    scene::ChangeSet changes;
    changes.addMaterial(scene, std::move(material));
    return changes;
}

util::Result<scene::ChangeSet> addObjectChange(const scene::Scene& scene, const std::string& meshPath,
                                               std::shared_ptr<const scene::TriangleMesh> mesh,
                                               const std::string& name) {
    std::string base = meshPath.substr(meshPath.find_last_of("/\\") + 1);
    base = base.substr(0, base.find('.'));
    auto picked = pickName(scene, EntityKind::Object, name, base.empty() ? "Object" : base, false);
    if (!picked) return picked.error();
    scene::ChangeSet changes;
    scene::Object object;
    if (scene.materials.empty()) {
        scene::Material material;
        material.id = scene.nextId();
        material.name = "default";
        object.materialId = material.id;
        changes.addMaterial(scene, std::move(material));
        object.id = object.materialId + 1;
    } else {
        object.materialId = scene.materials.front().id;
        object.id = scene.nextId();
    }
    object.name = *picked;
    object.meshPath = meshPath;
    object.mesh = std::move(mesh);
    changes.addObject(scene, std::move(object));
    return changes;
}

util::Result<scene::ChangeSet> removeChange(const scene::Scene& scene, EntityRef ref) {
    if (ref.kind == EntityKind::Material) {
        std::string users;
        for (const scene::Object& o : scene.objects)
            if (o.materialId == ref.id) users += (users.empty() ? "'" : ", '") + o.name + "'";
        if (!users.empty()) {
            std::string message = "material '";
            message += entityName(scene, ref);
            message += "' is used by ";
            message += users;
            message += ": give those objects another material first";
            return makeError(ErrorKind::Invalid, "", message);
        }
    }
    scene::ChangeSet changes;
    if (auto status = changes.removeEntity(scene, ref); !status) return status.error();
    return changes;
}

util::Result<scene::ChangeSet> duplicateChange(const scene::Scene& scene, EntityRef ref) {
    scene::ChangeSet changes;
    auto copyName = [&](const std::string& name) {
        return pickName(scene, ref.kind, "", name + " copy", false);
    };
    if (const scene::Light* light = scene.findLight(ref.kind == EntityKind::Light ? ref.id : 0)) {
        scene::Light copy = *light;
        copy.id = scene.nextId();
        copy.name = *copyName(light->name);
        changes.addLight(scene, std::move(copy));
    } else if (const scene::Object* object = scene.findObject(ref.kind == EntityKind::Object ? ref.id : 0)) {
        scene::Object copy = *object;
        copy.id = scene.nextId();
        copy.name = *copyName(object->name);
        changes.addObject(scene, std::move(copy));
    } else if (const scene::Material* material =
                   scene.findMaterial(ref.kind == EntityKind::Material ? ref.id : 0)) {
        scene::Material copy = *material;
        copy.id = scene.nextId();
        copy.name = *copyName(material->name);
        changes.addMaterial(scene, std::move(copy));
    } else {
        return makeError(ErrorKind::Invalid, "",
                         std::string("cannot duplicate the ") + scene::entityKindName(ref.kind) +
                             (ref.kind == EntityKind::Light || ref.kind == EntityKind::Object ||
                                      ref.kind == EntityKind::Material
                                  ? " (it is not in the scene)"
                                  : ""));
    }
    return changes;
}

util::Status checkRename(const scene::Scene& scene, EntityRef ref, const std::string& name) {
    if (name.empty()) return makeError(ErrorKind::Invalid, "", "a name cannot be empty");
    if (entityName(scene, ref) == name) return util::okStatus();
    if (nameTaken(scene, ref.kind, name))
        return makeError(ErrorKind::Invalid, "",
                         std::string("a ") + scene::entityKindName(ref.kind) + " named '" + name +
                             "' already exists");
    return util::okStatus();
}

std::optional<EntityRef> addedEntity(const scene::ChangeSet& changes) {
    std::optional<EntityRef> last;
    for (const scene::Edit& edit : changes.edits())
        if (const auto* e = std::get_if<scene::EntityEdit>(&edit); e && e->add) last = e->ref();
    return last; // the last one: an object added with its default material is the object
}

} // namespace wavelit::editor
