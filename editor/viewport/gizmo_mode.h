// The viewport gizmo's mode (viewport_interaction.h): W moves, E rotates, as in Blender and Maya.
#pragma once

#include <QMetaType>

#include <optional>
#include <string_view>

namespace wavelit::editor {

enum class GizmoMode { Move, Rotate };

inline const char* gizmoModeName(GizmoMode mode) { return mode == GizmoMode::Move ? "move" : "rotate"; }

inline std::optional<GizmoMode> gizmoModeFromName(std::string_view name) {
    if (name == "move") return GizmoMode::Move;
    if (name == "rotate") return GizmoMode::Rotate;
    return std::nullopt;
}

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::editor::GizmoMode)
