#include "relight/edit_list.h"

#include "scene/property_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace wavelit::relight {
namespace {

using util::ErrorKind;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

template <class Entity>
std::optional<scene::EntityId> named(const std::vector<Entity>& list, const std::string& name) {
    for (const Entity& e : list)
        if (e.name == name) return e.id;
    return std::nullopt;
}

std::optional<scene::EntityRef> ofKind(const scene::Scene& s, scene::EntityKind kind, const std::string& name) {
    std::optional<scene::EntityId> id;
    if (kind == scene::EntityKind::Light) id = named(s.lighting.lights, name);
    if (kind == scene::EntityKind::Object) id = named(s.objects, name);
    if (kind == scene::EntityKind::Material) id = named(s.materials, name);
    if (!id) return std::nullopt;
    return scene::EntityRef{kind, *id};
}

} // namespace

util::Result<scene::EntityRef> resolveEntityName(const scene::Scene& scene, const std::string& text) {
    const std::string key = lower(text);
    for (scene::EntityKind k : {scene::EntityKind::Camera, scene::EntityKind::Environment, scene::EntityKind::Render})
        if (key == scene::entityKindName(k)) return scene::EntityRef{k, scene::kInvalidId};
    if (const size_t colon = text.find(':'); colon != std::string::npos) {
        const std::string kind = lower(text.substr(0, colon)), name = text.substr(colon + 1);
        for (scene::EntityKind k : {scene::EntityKind::Light, scene::EntityKind::Object, scene::EntityKind::Material})
            if (kind == scene::entityKindName(k)) {
                if (auto ref = ofKind(scene, k, name)) return *ref;
                return util::makeError(ErrorKind::Invalid, "", "no entity named '" + text + "'");
            }
    }
    std::vector<scene::EntityRef> matches;
    for (scene::EntityKind k : {scene::EntityKind::Light, scene::EntityKind::Object, scene::EntityKind::Material})
        if (auto ref = ofKind(scene, k, text)) matches.push_back(*ref);
    if (matches.size() == 1) return matches.front();
    if (matches.empty()) return util::makeError(ErrorKind::Invalid, "", "no entity named '" + text + "'");
    return util::makeError(ErrorKind::Invalid, "", "'" + text + "' is ambiguous (use kind:name)");
}

util::Result<std::vector<PlannedEdit>> readEditList(const std::string& path, const scene::Scene& scene) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return util::makeError(ErrorKind::NotFound, path, "cannot open the edits file");
    std::stringstream text;
    text << in.rdbuf();
    scene::Json root;
    try {
        root = scene::Json::parse(text.str());
    } catch (const std::exception& e) {
        return util::makeError(ErrorKind::Format, path, std::string("not valid JSON: ") + e.what());
    }
    if (!root.is_array())
        return util::makeError(ErrorKind::Format, path, "expected a JSON array of {entity, property, value}");
    scene::Scene current = scene;
    std::vector<PlannedEdit> out;
    for (size_t i = 0; i < root.size(); ++i) {
        std::string where = "/"; // not "/" + to_string(i): GCC 12 warns falsely (-Wrestrict)
        where += std::to_string(i);
        const scene::JsonPlace at{path, where};
        const scene::Json& e = root[i];
        auto bad = [&](const std::string& why) { return scene::jsonError(ErrorKind::Invalid, at, why); };
        if (!e.is_object()) return bad("expected an object {entity, property, value}");
        for (auto it = e.begin(); it != e.end(); ++it)
            if (it.key() != "entity" && it.key() != "property" && it.key() != "value")
                return bad("unknown key '" + it.key() + "' (an edit has entity, property, value)");
        if (!e.contains("entity") || !e["entity"].is_string()) return bad("'entity' must be a string");
        if (!e.contains("property") || !e["property"].is_string()) return bad("'property' must be a string");
        if (!e.contains("value")) return bad("missing 'value'");
        PlannedEdit edit{e["entity"].get<std::string>(), e["property"].get<std::string>(), {}};
        auto ref = resolveEntityName(current, edit.entity);
        if (!ref) return bad(ref.error().reason);
        const scene::PropertyInfo* info = scene::findProperty(ref.value().kind, edit.property);
        if (!info)
            return bad("unknown property '" + edit.property + "' of " + scene::entityKindName(ref.value().kind));
        if (info->type == scene::PropertyType::Path)
            return bad(edit.property + ": file edits are not previewed (the file is loaded with the scene)");
        scene::Json value = e["value"];
        if (info->type == scene::PropertyType::IdRef && value.is_string()) {
            // A plain name names an entity of the kind the property refers to ("ground" is the
            // material even when an object is called so too); "kind:name" as anywhere else.
            const std::string name = value.get<std::string>();
            std::optional<scene::EntityRef> target = ofKind(current, info->refersTo, name);
            if (!target)
                if (auto r = resolveEntityName(current, name); r && r.value().kind == info->refersTo) target = r.value();
            if (!target)
                return bad(edit.property + ": no " + scene::entityKindName(info->refersTo) + " named '" + name + "'");
            value = target->id;
        }
        auto converted = scene::valueFromJson(value, *info, at.child("value"));
        if (!converted) return converted.error();
        if (auto st = edit.changes.setProperty(current, ref.value(), edit.property, converted.value()); !st)
            return bad(st.error().reason);
        if (auto st = edit.changes.apply(current); !st) return bad(st.error().reason);
        out.push_back(std::move(edit));
    }
    return out;
}

} // namespace wavelit::relight
