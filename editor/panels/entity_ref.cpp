#include "panels/entity_ref.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace wavelit::editor {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

constexpr EntityKind kNamedKinds[] = {EntityKind::Light, EntityKind::Object, EntityKind::Material};

std::optional<EntityRef> singleton(const std::string& text) {
    const std::string key = lower(text);
    if (key == "camera") return EntityRef{EntityKind::Camera, scene::kInvalidId};
    if (key == "environment") return EntityRef{EntityKind::Environment, scene::kInvalidId};
    if (key == "render") return EntityRef{EntityKind::Render, scene::kInvalidId};
    return std::nullopt;
}

util::Error noEntity(const std::string& text) {
    return util::makeError(util::ErrorKind::Invalid, "", "no entity named '" + text + "'");
}

} // namespace

std::optional<EntityRef> findEntityOfKind(const scene::Scene& scene, EntityKind kind, const std::string& name) {
    auto find = [&](const auto& entities) -> std::optional<EntityRef> {
        for (const auto& e : entities)
            if (e.name == name) return EntityRef{kind, e.id};
        return std::nullopt;
    };
    switch (kind) {
    case EntityKind::Light: return find(scene.lighting.lights);
    case EntityKind::Object: return find(scene.objects);
    case EntityKind::Material: return find(scene.materials);
    default: return std::nullopt;
    }
}

util::Result<EntityRef> resolveEntity(const scene::Scene& scene, const std::string& text) {
    if (auto ref = singleton(text)) return *ref;
    if (const size_t colon = text.find(':'); colon != std::string::npos) {
        const std::string kindName = lower(text.substr(0, colon));
        const std::string name = text.substr(colon + 1);
        for (EntityKind kind : scene::kAllEntityKinds) {
            if (kindName != scene::entityKindName(kind)) continue;
            if (auto ref = singleton(kindName); ref && name.empty()) return *ref; // "camera:"
            if (auto ref = findEntityOfKind(scene, kind, name)) return *ref;
            return noEntity(text);
        }
        // Not a kind prefix: a plain name that contains ':' (names are free text).
    }
    std::vector<EntityRef> matches;
    for (EntityKind kind : kNamedKinds)
        if (auto ref = findEntityOfKind(scene, kind, text)) matches.push_back(*ref);
    if (matches.empty()) return noEntity(text);
    if (matches.size() == 1) return matches.front();
    std::string candidates;
    for (const EntityRef& ref : matches)
        candidates += (candidates.empty() ? "" : ", ") + qualifiedName(scene, ref);
    return util::makeError(util::ErrorKind::Invalid, "",
                           "'" + text + "' is ambiguous: " + candidates + " (use kind:name)");
}

std::optional<EntityRef> findEntityByName(const scene::Scene& scene, const std::string& name) {
    auto ref = resolveEntity(scene, name);
    if (!ref) return std::nullopt;
    return ref.value();
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

std::string qualifiedName(const scene::Scene& scene, EntityRef ref) {
    if (singleton(scene::entityKindName(ref.kind))) return scene::entityKindName(ref.kind);
    return std::string(scene::entityKindName(ref.kind)) + ":" + entityName(scene, ref);
}

} // namespace wavelit::editor
