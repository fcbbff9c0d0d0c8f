// The rows a property panel shows for one entity, generated from the property registry
// (scene/property_registry.h): one row per applicable property, in registry order, so a new
// property appears in the panel without editor code. Qt-free data so tests compare it directly.
#pragma once

#include "panels/entity_ref.h"

#include <string>
#include <vector>

namespace wavelit::editor {

struct PropertyRow {
    const scene::PropertyInfo* info = nullptr; // label, unit, tooltip, type, change kind
    std::string value;                          // display text: "0.25", "[1, 0.5, 0]", "Gold"
};

// Empty when the entity no longer exists (e.g. deleted while selected).
std::vector<PropertyRow> propertyRows(const scene::Scene& scene, EntityRef ref);

// Display text of one value: IdRef values show the referenced entity's name.
std::string displayValue(const scene::Scene& scene, const scene::PropertyInfo& info,
                         const scene::PropertyValue& value);

} // namespace wavelit::editor
