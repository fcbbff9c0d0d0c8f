// How panels, commands and scripts name one editable thing: the registry's scene::EntityRef
// (kind + stable id; Camera, Environment and Render are singletons). Scripts name entities by
// display name, resolved here.
#pragma once

#include "scene/property_registry.h"

#include <QMetaType>

#include <optional>
#include <string>

namespace wavelit::editor {

using scene::EntityKind;
using scene::EntityRef;

// "camera", "environment" and "render" (case-insensitive) name the singletons; otherwise the
// first light, object or material with exactly that name, in that order.
std::optional<EntityRef> findEntityByName(const scene::Scene& scene, const std::string& name);

// The entity's display name ("Camera", "Environment", "Render", or its name); empty if missing.
std::string entityName(const scene::Scene& scene, EntityRef ref);

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::scene::EntityRef)
