#include "panels/entity_ref.h"

#include <algorithm>
#include <cctype>

namespace wavelit::editor {
namespace {
std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}
} // namespace

std::optional<EntityRef> findEntityByName(const scene::Scene& scene, const std::string& name) {
    const std::string key = lower(name);
    if (key == "camera") return EntityRef{EntityKind::Camera, scene::kInvalidId};
    if (key == "environment") return EntityRef{EntityKind::Environment, scene::kInvalidId};
    if (key == "render") return EntityRef{EntityKind::Render, scene::kInvalidId};
    for (const auto& l : scene.lighting.lights)
        if (l.name == name) return EntityRef{EntityKind::Light, l.id};
    for (const auto& o : scene.objects)
        if (o.name == name) return EntityRef{EntityKind::Object, o.id};
    for (const auto& m : scene.materials)
        if (m.name == name) return EntityRef{EntityKind::Material, m.id};
    return std::nullopt;
}

std::string entityName(const scene::Scene& scene, EntityRef ref) {
    switch (ref.kind) {
    case EntityKind::Camera: return "Camera";
    case EntityKind::Environment: return "Environment";
    case EntityKind::Render: return "Render";
    case EntityKind::Light:
        if (auto* l = scene.findLight(ref.id)) return l->name;
        break;
    case EntityKind::Object:
        if (auto* o = scene.findObject(ref.id)) return o->name;
        break;
    case EntityKind::Material:
        if (auto* m = scene.findMaterial(ref.id)) return m->name;
        break;
    }
    return {};
}

} // namespace wavelit::editor
