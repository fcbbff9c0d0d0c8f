// How panels, commands and scripts name one editable thing: the registry's scene::EntityRef
// (kind + stable id; Camera, Environment and Render are singletons). Scripts and the outline name
// entities by text, resolved here:
//   "camera", "environment", "render"   the singletons (case-insensitive);
//   "kind:name"                         e.g. "material:ground", "object:ground", "light:sun";
//   "name"                              a light, object or material, when exactly one has it.
// Names are unique per kind (scene validation), so "kind:name" always resolves to at most one
// entity; a plain name that two kinds share is an error naming every candidate.
#pragma once

#include "scene/property_registry.h"
#include "util/result.h"

#include <QMetaType>

#include <optional>
#include <string>

namespace wavelit::editor {

using scene::EntityKind;
using scene::EntityRef;

// The entity a name or "kind:name" designates; the error says "no entity named 'x'" or lists the
// candidates of an ambiguous plain name ("'ground' is ambiguous: material:ground, object:ground").
util::Result<EntityRef> resolveEntity(const scene::Scene& scene, const std::string& text);

// resolveEntity without the reason (nullopt when missing or ambiguous).
std::optional<EntityRef> findEntityByName(const scene::Scene& scene, const std::string& name);

// The light, object or material of `kind` with exactly this name.
std::optional<EntityRef> findEntityOfKind(const scene::Scene& scene, EntityKind kind, const std::string& name);

// The entity's display name ("Camera", "Environment", "Render", or its name); empty if missing.
std::string entityName(const scene::Scene& scene, EntityRef ref);

// The name that resolves to exactly this entity: "camera", "environment", "render" or
// "kind:name" ("material:ground").
std::string qualifiedName(const scene::Scene& scene, EntityRef ref);

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::scene::EntityRef)
