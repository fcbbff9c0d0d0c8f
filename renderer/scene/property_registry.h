// The property registry: every editable field of every entity type is declared here once — name
// (the JSON key and the script name), label, type, unit, range, default, tooltip, what an edit costs
// (ChangeKind) and which cached factor it invalidates (architecture.md §5). JSON reading/writing
// (property_json.h), validation, change sets (change_set.h), the editor's panels and scripting are
// all driven from this table, so adding a property is one declaration (architecture.md §9 "one registry").
// Qt-free; the tables are immutable after first use and safe to read from any thread.
#pragma once

#include "scene/property_value.h"
#include "scene/scene.h"
#include "util/result.h"

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace wavelit::scene {

enum class EntityKind { Camera, Material, Object, Environment, Light, Render };
inline constexpr EntityKind kAllEntityKinds[] = {EntityKind::Camera, EntityKind::Material,
                                                 EntityKind::Object, EntityKind::Environment,
                                                 EntityKind::Light,  EntityKind::Render};
const char* entityKindName(EntityKind kind); // "camera", "material", ... (script/JSON names)

enum class PropertyType { Bool, Int, Float, Vec2, Vec3, Color, String, Enum, Path, IdRef };
const char* propertyTypeName(PropertyType type);

// What an edit costs the renderer (architecture.md §9 "Threads"): Display = tone mapping only, never resets
// accumulation; Restart = reset accumulation; Rebuild = geometry changed: BVH rebuild + restart.
enum class ChangeKind { Display, Restart, Rebuild };

// The cached factor an edit makes stale (architecture.md §5 A: L, L_k, O_j, BRDF, camera).
// ObjectMaterial(j): object j now uses another material, so its vertices' BRDF factor changes.
enum class FactorKind { None, Environment, Light, ObjectGeometry, ObjectMaterial, MaterialBrdf, Camera };
const char* factorKindName(FactorKind kind);

struct Invalidation {
    FactorKind factor = FactorKind::None;
    EntityId id = kInvalidId; // light / object / material id; kInvalidId for env and camera
    auto operator<=>(const Invalidation&) const = default;
};

// True when `changed` is non-empty and every invalidation is of `kind` (e.g. a light drag: only
// Light), so whatever depends on the other factors alone may be kept.
bool onlyFactor(const std::vector<Invalidation>& changed, FactorKind kind);
// The same for a set of kinds: every invalidation is of one of them.
bool onlyFactors(const std::vector<Invalidation>& changed,
                 std::initializer_list<FactorKind> kinds);

// Names one entity of a scene. Camera, Environment and Render are singletons: id is ignored.
struct EntityRef {
    EntityKind kind = EntityKind::Camera;
    EntityId id = kInvalidId;
    auto operator<=>(const EntityRef&) const = default;
};

struct PropertyInfo {
    EntityKind entity = EntityKind::Camera;
    std::string name;  // JSON key and script name: "roughness"
    std::string label; // panel label: "Roughness"
    PropertyType type = PropertyType::Float;
    std::string unit;  // "m", "deg", "W", "EV", "" for dimensionless
    double min = -1e30, max = 1e30; // hard range, per component for vectors
    PropertyValue defaultValue;
    std::string tooltip;
    ChangeKind change = ChangeKind::Restart;
    FactorKind factor = FactorKind::None;
    std::vector<std::string> enumOptions;  // Enum: the allowed strings
    std::string enumNoun; // Enum: what an option names, for messages ("BRDF"); empty: a plain choice
    std::vector<LightType> lightTypes;     // Light properties: the types it applies to (empty: all)
    EntityKind refersTo = EntityKind::Material; // IdRef: the kind it names
    bool required = false; // a file must state it (no sensible default: mesh, material, type)
    bool omitWhenDefault = false; // JSON leaves it out at its default (keeps older files as they were)
    // Accessors on the entity struct the kind names (Camera, Material, Object, Environment,
    // Light, RenderDefaults). set() expects a value that passed checkValue().
    std::function<PropertyValue(const void*)> get;
    std::function<void(void*, const PropertyValue&)> set;
};

const std::vector<PropertyInfo>& properties(EntityKind kind);
const PropertyInfo* findProperty(EntityKind kind, std::string_view name);

// True when the property means something for this entity (a Sun has no radius). JSON writes only
// applicable properties; reading lists the others as problems (property_json.h), since a save
// would drop them.
bool propertyApplies(const PropertyInfo& info, const void* entity);

// Type, range, enum option and path checks. The error's reason names the property.
util::Status checkValue(const PropertyInfo& info, const PropertyValue& value);

// Why `value` is not an option of Enum `info`, without the property name: "unknown BRDF 'phong';
// known: lambert, ggx" when the property has an enumNoun, else "'laser' is not one of point, ...".
std::string unknownOptionMessage(const PropertyInfo& info, const std::string& value);

// Absolute paths and home-relative paths are rejected: files must stay movable (architecture.md §6).
bool isPortableRelativePath(const std::string& path);

// Entity lookup and generic get/set by property name on a scene.
const void* findEntity(const Scene& scene, EntityRef ref);
void* findEntity(Scene& scene, EntityRef ref);
util::Result<PropertyValue> getProperty(const Scene& scene, EntityRef ref, std::string_view name);
util::Status setProperty(Scene& scene, EntityRef ref, std::string_view name, const PropertyValue& value);

// The factor an edit of this property of this entity invalidates.
Invalidation invalidationFor(const PropertyInfo& info, EntityRef ref);

} // namespace wavelit::scene
