// Small rules over a change set that RelightPreview's full update (relight_edits.cpp), the
// material edit's first answer (material_first_answer.cpp) and the shadow-field drag
// (field_drag.cpp, coarse_to_fine.cpp) apply, so that they decide alike which edits change
// nothing per point and which a field drag takes.
#pragma once

#include "scene/change_set.h"

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

namespace wavelit::relight {

// Index of the entity with `id` in `list` (objects, materials, lights); list.size() if none.
template <class Entity> size_t indexOf(const std::vector<Entity>& list, scene::EntityId id) {
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i].id == id) return i;
    return list.size();
}

// True when every edit of `ref` in the change set is one of `scalers` (a light's intensity and
// colour, the environment's intensity and tint, a material's emission): those terms are cached
// per unit power (environment_factor.h, light_projection.h), so nothing per point changes.
inline bool onlyScales(const scene::ChangeSet& changes, scene::EntityRef ref,
                       std::initializer_list<std::string_view> scalers) {
    for (const scene::Edit& e : changes.edits()) {
        const auto* edit = std::get_if<scene::PropertyEdit>(&e);
        if (!edit || edit->entity != ref) continue;
        if (std::find(scalers.begin(), scalers.end(), edit->property) == scalers.end()) return false;
    }
    return true;
}

// The object whose translation is every edit of the change set (a drag's frames), if they all
// translate one object; none for an empty set or any other edit. A shadow field's drag takes
// exactly these (relight_preview.h isFieldDrag, coarse_to_fine.h).
inline std::optional<scene::EntityId> onlyTranslatedObject(const scene::ChangeSet& changes) {
    std::optional<scene::EntityId> object;
    for (const scene::Edit& e : changes.edits()) {
        const auto* edit = std::get_if<scene::PropertyEdit>(&e);
        if (!edit || edit->entity.kind != scene::EntityKind::Object || edit->property != "translation" ||
            (object && edit->entity.id != *object))
            return std::nullopt;
        object = edit->entity.id;
    }
    return object;
}

} // namespace wavelit::relight
