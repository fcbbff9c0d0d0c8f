// The declarations: one block per entity kind. Units and ranges follow scene.h; the change kind
// and factor follow architecture.md §5 (env edit -> L, light k -> L_k, object j -> O_j + BVH,
// material m -> its BRDF factor, camera -> all BRDF factors toward the view).
#include "scene/property_registry.h"

#include "plugins/brdf.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <type_traits>

namespace wavelit::scene {

using util::ErrorKind;
using util::makeError;

namespace {

constexpr double kUnbounded = 1e30;

// A chainable declaration so each property reads as one statement.
struct Decl {
    PropertyInfo& p;
    Decl& unit(const char* u) { p.unit = u; return *this; }
    Decl& range(double lo, double hi) { p.min = lo; p.max = hi; return *this; }
    Decl& tip(const char* t) { p.tooltip = t; return *this; }
    Decl& cost(ChangeKind c, FactorKind f) { p.change = c; p.factor = f; return *this; }
    Decl& options(std::vector<std::string> o) { p.enumOptions = std::move(o); return *this; }
    Decl& noun(const char* n) { p.enumNoun = n; return *this; }
    Decl& lights(std::vector<LightType> t) { p.lightTypes = std::move(t); return *this; }
    Decl& required() { p.required = true; return *this; }
    Decl& omitWhenDefault() { p.omitWhenDefault = true; return *this; }
};

// Declares a property backed directly by a member (member type = the variant alternative).
template <typename E, typename F>
Decl field(std::vector<PropertyInfo>& list, EntityKind kind, const char* name, const char* label,
           PropertyType type, F E::*member) {
    PropertyInfo p;
    p.entity = kind;
    p.name = name;
    p.label = label;
    p.type = type;
    p.defaultValue = PropertyValue(E{}.*member);
    p.get = [member](const void* e) { return PropertyValue(static_cast<const E*>(e)->*member); };
    p.set = [member](void* e, const PropertyValue& v) { static_cast<E*>(e)->*member = std::get<F>(v); };
    list.push_back(std::move(p));
    return Decl{list.back()};
}

// Declares a property through custom accessors (nested members, enums, paths owning assets).
template <typename E>
Decl custom(std::vector<PropertyInfo>& list, EntityKind kind, const char* name, const char* label,
            PropertyType type, std::function<PropertyValue(const E&)> get,
            std::function<void(E&, const PropertyValue&)> set) {
    PropertyInfo p;
    p.entity = kind;
    p.name = name;
    p.label = label;
    p.type = type;
    p.defaultValue = get(E{});
    p.get = [get](const void* e) { return get(*static_cast<const E*>(e)); };
    p.set = [set](void* e, const PropertyValue& v) { set(*static_cast<E*>(e), v); };
    list.push_back(std::move(p));
    return Decl{list.back()};
}

const std::vector<std::string> kLightTypeNames = {"point", "sphere", "rect", "spot", "sun"};

std::vector<PropertyInfo> declareCamera() {
    std::vector<PropertyInfo> l;
    const auto K = EntityKind::Camera;
    field(l, K, "position", "Position", PropertyType::Vec3, &Camera::position).unit("m")
        .tip("Eye position in world space").cost(ChangeKind::Restart, FactorKind::Camera);
    field(l, K, "target", "Target", PropertyType::Vec3, &Camera::target).unit("m")
        .tip("Point the camera looks at").cost(ChangeKind::Restart, FactorKind::Camera);
    field(l, K, "up", "Up", PropertyType::Vec3, &Camera::up)
        .tip("Up hint; need not be orthogonal to the view direction")
        .cost(ChangeKind::Restart, FactorKind::Camera);
    field(l, K, "fov", "Vertical FOV", PropertyType::Float, &Camera::verticalFovDeg).unit("deg")
        .range(1.0, 179.0).tip("Vertical field of view").cost(ChangeKind::Restart, FactorKind::Camera);
    field(l, K, "exposure", "Exposure", PropertyType::Float, &Camera::exposureEv).unit("EV")
        .range(-30.0, 30.0).tip("Display exposure; never resets accumulation")
        .cost(ChangeKind::Display, FactorKind::None);
    return l;
}

std::vector<PropertyInfo> declareMaterial() {
    std::vector<PropertyInfo> l;
    const auto K = EntityKind::Material;
    field(l, K, "name", "Name", PropertyType::String, &Material::name)
        .tip("Unique among materials").cost(ChangeKind::Display, FactorKind::None);
    // The options are the plugin registry's names, so a file, a script or the panel's combo box
    // can only name a BRDF the renderer has.
    const std::vector<std::string> brdfs = plugins::brdfNames();
    std::string brdfTip = "BRDF plugin (plugins/):";
    for (const std::string& b : brdfs) brdfTip += " " + b;
    field(l, K, "brdf", "BRDF", PropertyType::Enum, &Material::brdf)
        .options(brdfs).noun("BRDF").required().tip(brdfTip.c_str())
        .cost(ChangeKind::Restart, FactorKind::MaterialBrdf);
    // The plugins' parameters: each tooltip quotes every plugin that reads it (plugins/brdf.h).
    auto brdfParameter = [&](const char* name, const char* label, PropertyType type, auto member) {
        return field(l, K, name, label, type, member).tip(plugins::brdfParameterTooltip(name).c_str())
            .cost(ChangeKind::Restart, FactorKind::MaterialBrdf);
    };
    brdfParameter("baseColor", "Base colour", PropertyType::Color, &Material::baseColor).range(0.0, 1.0);
    brdfParameter("roughness", "Roughness", PropertyType::Float, &Material::roughness).range(0.0, 1.0);
    brdfParameter("anisotropy", "Anisotropy", PropertyType::Float, &Material::anisotropy).range(0.0, 1.0);
    // Relative to the scene; scene_io's loadAssets() (re)loads the table it names.
    brdfParameter("brdfFile", "BRDF data file", PropertyType::Path, &Material::brdfFile);
    field(l, K, "emission", "Emission", PropertyType::Color, &Material::emission).unit("W/(m^2 sr)")
        .range(0.0, kUnbounded).tip("Emitted radiance").cost(ChangeKind::Restart, FactorKind::MaterialBrdf);
    return l;
}

std::vector<PropertyInfo> declareObject() {
    std::vector<PropertyInfo> l;
    const auto K = EntityKind::Object;
    field(l, K, "name", "Name", PropertyType::String, &Object::name)
        .tip("Unique among objects").cost(ChangeKind::Display, FactorKind::None);
    // A new path drops the loaded mesh; scene_io's loadAssets() loads it again.
    custom<Object>(l, K, "mesh", "Mesh file", PropertyType::Path,
        [](const Object& o) { return PropertyValue(o.meshPath); },
        [](Object& o, const PropertyValue& v) {
            if (o.meshPath != std::get<std::string>(v)) o.mesh.reset();
            o.meshPath = std::get<std::string>(v);
        })
        .required().tip("Mesh file (OBJ, glTF, PLY, FBX...) relative to the scene file")
        .cost(ChangeKind::Rebuild, FactorKind::ObjectGeometry);
    custom<Object>(l, K, "translation", "Translation", PropertyType::Vec3,
        [](const Object& o) { return PropertyValue(o.transform.translation); },
        [](Object& o, const PropertyValue& v) { o.transform.translation = std::get<glm::vec3>(v); })
        .unit("m").tip("Applied last (T * R * S)").cost(ChangeKind::Rebuild, FactorKind::ObjectGeometry);
    custom<Object>(l, K, "rotation", "Rotation", PropertyType::Vec3,
        [](const Object& o) { return PropertyValue(o.transform.rotationDeg); },
        [](Object& o, const PropertyValue& v) { o.transform.rotationDeg = std::get<glm::vec3>(v); })
        .unit("deg").range(-360.0, 360.0).tip("Euler angles, X applied first, then Y, then Z")
        .cost(ChangeKind::Rebuild, FactorKind::ObjectGeometry);
    custom<Object>(l, K, "scale", "Scale", PropertyType::Vec3,
        [](const Object& o) { return PropertyValue(o.transform.scale); },
        [](Object& o, const PropertyValue& v) { o.transform.scale = std::get<glm::vec3>(v); })
        .range(1e-6, 1e6).tip("Per-axis scale; must be positive (mirroring flips normals)")
        .cost(ChangeKind::Rebuild, FactorKind::ObjectGeometry);
    field(l, K, "material", "Material", PropertyType::IdRef, &Object::materialId)
        .required().tip("Id of the material the object uses").cost(ChangeKind::Restart, FactorKind::ObjectMaterial);
    return l;
}

std::vector<PropertyInfo> declareEnvironment() {
    std::vector<PropertyInfo> l;
    const auto K = EntityKind::Environment;
    custom<Environment>(l, K, "map", "Map", PropertyType::Path,
        [](const Environment& e) { return PropertyValue(e.path); },
        [](Environment& e, const PropertyValue& v) {
            if (e.path != std::get<std::string>(v)) e.image.reset();
            e.path = std::get<std::string>(v);
        })
        .tip("Equirectangular HDR image (.exr/.hdr) relative to the file; empty = constant")
        .cost(ChangeKind::Restart, FactorKind::Environment);
    field(l, K, "rotation", "Rotation", PropertyType::Float, &Environment::rotationDeg).unit("deg")
        .range(-360.0, 360.0).tip("Yaw about +Y").cost(ChangeKind::Restart, FactorKind::Environment);
    field(l, K, "intensity", "Intensity", PropertyType::Float, &Environment::intensity)
        .range(0.0, kUnbounded).tip("Radiance scale").cost(ChangeKind::Restart, FactorKind::Environment);
    field(l, K, "tint", "Tint", PropertyType::Color, &Environment::tint).range(0.0, kUnbounded)
        .tip("Per-channel radiance scale").cost(ChangeKind::Restart, FactorKind::Environment);
    // LightMix "Extract sun" (docs/lightmix.md): the mask is applied where the map is loaded, so a
    // changed mask drops the loaded image like a changed path does.
    custom<Environment>(l, K, "maskDirection", "Mask direction", PropertyType::Vec3,
        [](const Environment& e) { return PropertyValue(e.maskDirection); },
        [](Environment& e, const PropertyValue& v) {
            if (e.maskDirection != std::get<glm::vec3>(v)) e.image.reset();
            e.maskDirection = std::get<glm::vec3>(v);
        })
        .range(-1.0, 1.0).omitWhenDefault()
        .tip("Centre of the masked cap, in the map's own frame (before rotation)")
        .cost(ChangeKind::Restart, FactorKind::Environment);
    custom<Environment>(l, K, "maskRadius", "Mask radius", PropertyType::Float,
        [](const Environment& e) { return PropertyValue(e.maskRadiusDeg); },
        [](Environment& e, const PropertyValue& v) {
            if (e.maskRadiusDeg != std::get<float>(v)) e.image.reset();
            e.maskRadiusDeg = std::get<float>(v);
        })
        .unit("deg").range(0.0, 90.0).omitWhenDefault()
        .tip("Angular radius of the cap whose texels count as black (an extracted sun); 0 = none")
        .cost(ChangeKind::Restart, FactorKind::Environment);
    return l;
}

std::vector<PropertyInfo> declareLight() {
    std::vector<PropertyInfo> l;
    const auto K = EntityKind::Light;
    const auto R = ChangeKind::Restart;
    const auto F = FactorKind::Light;
    using T = LightType;
    field(l, K, "name", "Name", PropertyType::String, &Light::name)
        .tip("Unique among lights").cost(ChangeKind::Display, FactorKind::None);
    custom<Light>(l, K, "type", "Type", PropertyType::Enum,
        [](const Light& x) { return PropertyValue(kLightTypeNames[size_t(x.type)]); },
        [](Light& x, const PropertyValue& v) {
            auto it = std::find(kLightTypeNames.begin(), kLightTypeNames.end(), std::get<std::string>(v));
            x.type = LightType(it - kLightTypeNames.begin());
        })
        .options(kLightTypeNames).required().tip("point, sphere, rect, spot or sun").cost(R, F);
    field(l, K, "color", "Colour", PropertyType::Color, &Light::color).range(0.0, kUnbounded)
        .tip("Multiplies intensity (usually luminance 1)").cost(R, F);
    field(l, K, "intensity", "Intensity", PropertyType::Float, &Light::intensity).range(0.0, kUnbounded)
        .unit("W or W/m^2").tip("Power in W; a sun's irradiance in W/m^2").cost(R, F);
    field(l, K, "position", "Position", PropertyType::Vec3, &Light::position).unit("m")
        .lights({T::Point, T::Sphere, T::Rect, T::Spot}).tip("Centre in world space").cost(R, F);
    field(l, K, "direction", "Direction", PropertyType::Vec3, &Light::direction)
        .lights({T::Rect, T::Spot, T::Sun}).tip("The way light travels").cost(R, F);
    field(l, K, "radius", "Radius", PropertyType::Float, &Light::radius).unit("m").range(0.0, kUnbounded)
        .lights({T::Sphere}).tip("Sphere light radius").cost(R, F);
    field(l, K, "size", "Size", PropertyType::Vec2, &Light::size).unit("m").range(0.0, kUnbounded)
        .lights({T::Rect}).tip("Width x height").cost(R, F);
    field(l, K, "coneInner", "Cone inner", PropertyType::Float, &Light::coneInnerDeg).unit("deg")
        .range(0.0, 90.0).lights({T::Spot}).tip("Full-intensity half angle").cost(R, F);
    field(l, K, "coneOuter", "Cone outer", PropertyType::Float, &Light::coneOuterDeg).unit("deg")
        .range(0.0, 90.0).lights({T::Spot}).tip("Cut-off half angle").cost(R, F);
    field(l, K, "angularDiameter", "Angular diameter", PropertyType::Float, &Light::angularDiameterDeg)
        .unit("deg").range(0.0, 90.0).lights({T::Sun}).tip("Apparent size (the Sun: 0.53)").cost(R, F);
    field(l, K, "group", "Light group", PropertyType::String, &Light::group).omitWhenDefault()
        .tip("LightMix layer shared with lights of the same group (empty: its own)").cost(R, F);
    field(l, K, "muted", "Muted", PropertyType::Bool, &Light::muted).omitWhenDefault().tip("Emits nothing").cost(R, F);
    return l;
}

std::vector<PropertyInfo> declareRender() {
    std::vector<PropertyInfo> l;
    const auto K = EntityKind::Render;
    field(l, K, "width", "Width", PropertyType::Int, &RenderDefaults::width).unit("px").range(1, 16384)
        .tip("Default image width").cost(ChangeKind::Restart, FactorKind::None);
    field(l, K, "height", "Height", PropertyType::Int, &RenderDefaults::height).unit("px").range(1, 16384)
        .tip("Default image height").cost(ChangeKind::Restart, FactorKind::None);
    field(l, K, "bounces", "Bounces", PropertyType::Int, &RenderDefaults::bounces).range(0, 64)
        .tip("Maximum path length in bounces").cost(ChangeKind::Restart, FactorKind::None);
    return l;
}

const std::map<EntityKind, std::vector<PropertyInfo>>& registry() {
    static const std::map<EntityKind, std::vector<PropertyInfo>> table = {
        {EntityKind::Camera, declareCamera()},       {EntityKind::Material, declareMaterial()},
        {EntityKind::Object, declareObject()},       {EntityKind::Environment, declareEnvironment()},
        {EntityKind::Light, declareLight()},         {EntityKind::Render, declareRender()},
    };
    return table;
}

template <typename E> auto* findIn(std::vector<E>& items, EntityId id) {
    auto it = std::find_if(items.begin(), items.end(), [id](const E& e) { return e.id == id; });
    return it == items.end() ? nullptr : &*it;
}

} // namespace

const char* entityKindName(EntityKind kind) {
    switch (kind) {
    case EntityKind::Camera: return "camera";
    case EntityKind::Material: return "material";
    case EntityKind::Object: return "object";
    case EntityKind::Environment: return "environment";
    case EntityKind::Light: return "light";
    case EntityKind::Render: return "render";
    }
    return "?";
}

const char* propertyTypeName(PropertyType type) {
    static const char* names[] = {"bool", "int", "float", "vec2", "vec3",
                                  "color", "string", "enum", "path", "id-ref"};
    return names[size_t(type)];
}

const char* factorKindName(FactorKind kind) {
    static const char* names[] = {"none", "environment", "light", "object-geometry",
                                  "object-material", "material-brdf", "camera"};
    return names[size_t(kind)];
}

bool onlyFactor(const std::vector<Invalidation>& changed, FactorKind kind) {
    return onlyFactors(changed, {kind});
}

bool onlyFactors(const std::vector<Invalidation>& changed,
                 std::initializer_list<FactorKind> kinds) {
    const auto listed = [&](const Invalidation& i) {
        return std::find(kinds.begin(), kinds.end(), i.factor) != kinds.end();
    };
    return !changed.empty() && std::all_of(changed.begin(), changed.end(), listed);
}

const std::vector<PropertyInfo>& properties(EntityKind kind) { return registry().at(kind); }

const PropertyInfo* findProperty(EntityKind kind, std::string_view name) {
    for (const PropertyInfo& p : properties(kind))
        if (p.name == name) return &p;
    return nullptr;
}

bool propertyApplies(const PropertyInfo& info, const void* entity) {
    if (info.entity != EntityKind::Light || info.lightTypes.empty()) return true;
    const LightType t = static_cast<const Light*>(entity)->type;
    return std::find(info.lightTypes.begin(), info.lightTypes.end(), t) != info.lightTypes.end();
}

const void* findEntity(const Scene& scene, EntityRef ref) {
    return findEntity(const_cast<Scene&>(scene), ref);
}

void* findEntity(Scene& scene, EntityRef ref) {
    switch (ref.kind) {
    case EntityKind::Camera: return &scene.camera;
    case EntityKind::Environment: return &scene.lighting.environment;
    case EntityKind::Render: return &scene.render;
    case EntityKind::Material: return findIn(scene.materials, ref.id);
    case EntityKind::Object: return findIn(scene.objects, ref.id);
    case EntityKind::Light: return findIn(scene.lighting.lights, ref.id);
    }
    return nullptr;
}

util::Result<PropertyValue> getProperty(const Scene& scene, EntityRef ref, std::string_view name) {
    const PropertyInfo* info = findProperty(ref.kind, name);
    if (!info)
        return makeError(ErrorKind::NotFound, "", std::string(entityKindName(ref.kind)) +
                                                      " has no property '" + std::string(name) + "'");
    const void* e = findEntity(scene, ref);
    if (!e)
        return makeError(ErrorKind::NotFound, "", std::string(entityKindName(ref.kind)) + " " +
                                                      std::to_string(ref.id) + " not found");
    return info->get(e);
}

util::Status setProperty(Scene& scene, EntityRef ref, std::string_view name, const PropertyValue& value) {
    const PropertyInfo* info = findProperty(ref.kind, name);
    if (!info)
        return makeError(ErrorKind::NotFound, "", std::string(entityKindName(ref.kind)) +
                                                      " has no property '" + std::string(name) + "'");
    void* e = findEntity(scene, ref);
    if (!e)
        return makeError(ErrorKind::NotFound, "", std::string(entityKindName(ref.kind)) + " " +
                                                      std::to_string(ref.id) + " not found");
    if (auto s = checkValue(*info, value); !s) return s;
    info->set(e, value);
    return util::okStatus();
}

Invalidation invalidationFor(const PropertyInfo& info, EntityRef ref) {
    switch (info.factor) {
    case FactorKind::None:
    case FactorKind::Environment:
    case FactorKind::Camera: return {info.factor, kInvalidId};
    default: return {info.factor, ref.id};
    }
}

} // namespace wavelit::scene
