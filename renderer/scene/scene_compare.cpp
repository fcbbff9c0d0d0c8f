#include "scene/scene_compare.h"

#include "scene/property_registry.h"

namespace wavelit::scene {

namespace {

std::string compareEntity(EntityKind kind, const void* a, const void* b, const std::string& label) {
    for (const PropertyInfo& info : properties(kind)) {
        const PropertyValue va = info.get(a), vb = info.get(b);
        if (va != vb) return label + " " + info.name + ": " + formatValue(va) + " != " + formatValue(vb);
    }
    return {};
}

std::string compareExtras(const std::string& a, const std::string& b, const std::string& label) {
    return a == b ? std::string() : label + " extras: " + (a.empty() ? "none" : a) + " != " + (b.empty() ? "none" : b);
}

template <typename E>
std::string compareList(EntityKind kind, const std::vector<E>& a, const std::vector<E>& b) {
    const std::string name = entityKindName(kind);
    if (a.size() != b.size())
        return std::to_string(a.size()) + " != " + std::to_string(b.size()) + " " + name + "s";
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].id != b[i].id)
            return name + " " + std::to_string(i) + " id: " + std::to_string(a[i].id) + " != " + std::to_string(b[i].id);
        if (auto d = compareEntity(kind, &a[i], &b[i], name + " #" + std::to_string(a[i].id)); !d.empty()) return d;
        if (auto d = compareExtras(a[i].extras, b[i].extras, name + " #" + std::to_string(a[i].id)); !d.empty()) return d;
    }
    return {};
}

} // namespace

std::string firstDifference(const LightingSetup& a, const LightingSetup& b) {
    if (a.name != b.name) return "lighting name: " + a.name + " != " + b.name;
    if (auto d = compareExtras(a.extras, b.extras, "lighting"); !d.empty()) return d;
    if (auto d = compareEntity(EntityKind::Environment, &a.environment, &b.environment, "environment"); !d.empty())
        return d;
    if (auto d = compareExtras(a.environment.extras, b.environment.extras, "environment"); !d.empty()) return d;
    return compareList(EntityKind::Light, a.lights, b.lights);
}

std::string firstDifference(const Scene& a, const Scene& b) {
    if (a.name != b.name) return "scene name: " + a.name + " != " + b.name;
    if (a.lightingPath != b.lightingPath) return "lighting path: " + a.lightingPath + " != " + b.lightingPath;
    if (auto d = compareExtras(a.extras, b.extras, "scene"); !d.empty()) return d;
    if (auto d = compareEntity(EntityKind::Camera, &a.camera, &b.camera, "camera"); !d.empty()) return d;
    if (auto d = compareExtras(a.camera.extras, b.camera.extras, "camera"); !d.empty()) return d;
    if (auto d = compareEntity(EntityKind::Render, &a.render, &b.render, "render"); !d.empty()) return d;
    if (auto d = compareExtras(a.render.extras, b.render.extras, "render"); !d.empty()) return d;
    if (auto d = compareList(EntityKind::Material, a.materials, b.materials); !d.empty()) return d;
    if (auto d = compareList(EntityKind::Object, a.objects, b.objects); !d.empty()) return d;
    return firstDifference(a.lighting, b.lighting);
}

} // namespace wavelit::scene
