// PropertyValue: the one value type every editable property travels in — through JSON IO, the
// change sets (undo), the editor's panels and the script API. A closed variant rather than a
// type-erased any, so that comparing, printing and converting values needs no per-property code.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <variant>

namespace wavelit::scene {

// Alternatives by PropertyType: Bool -> bool; Int -> int; Float -> float; Vec2 -> glm::vec2;
// Vec3/Color -> glm::vec3; String/Enum/Path -> std::string; IdRef -> EntityId.
using PropertyValue = std::variant<bool, int, float, glm::vec2, glm::vec3, std::string, EntityId>;

// A short human-readable form for messages and logs: 0.2, [1, 0.5, 0], "gold", #7.
std::string formatValue(const PropertyValue& value);

} // namespace wavelit::scene
