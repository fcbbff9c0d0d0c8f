#include "panels/property_rows.h"

#include <variant>

namespace wavelit::editor {

std::string displayValue(const scene::Scene& scene, const scene::PropertyInfo& info,
                         const scene::PropertyValue& value) {
    if (info.type == scene::PropertyType::IdRef) {
        if (const auto* id = std::get_if<scene::EntityId>(&value)) {
            std::string name = entityName(scene, EntityRef{info.refersTo, *id});
            if (!name.empty()) return name;
        }
    }
    return scene::formatValue(value);
}

std::vector<PropertyRow> propertyRows(const scene::Scene& scene, EntityRef ref) {
    std::vector<PropertyRow> rows;
    const void* entity = scene::findEntity(scene, ref);
    if (!entity) return rows;
    for (const scene::PropertyInfo& info : scene::properties(ref.kind)) {
        if (!scene::propertyApplies(info, entity) || !info.get) continue;
        rows.push_back({&info, displayValue(scene, info, info.get(entity))});
    }
    return rows;
}

} // namespace wavelit::editor
