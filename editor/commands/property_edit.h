// PropertyEdit: one property change as a value (the unit the undo stack and the render queue will
// carry, architecture.md §9 "Threads"). apply() checks the value against the registry and returns the edited
// scene copy (meshes and images are shared, so a copy is cheap) plus what the edit costs: a
// Display edit (exposure) only re-tone-maps, Restart/Rebuild edits go to the render thread.
#pragma once

#include "panels/entity_ref.h"

#include "util/result.h"

#include <QMetaType>

#include <memory>
#include <string>

namespace wavelit::editor {

// A gesture is one continuous user action that sends many values: a slider drag, a spin-box
// scrub (arrow held, wheel), a viewport drag. Its edits share a GestureId and undo as one step;
// edits without a gesture (kNoGesture: typed values, menu actions, script calls) never merge.
using GestureId = quint64;
inline constexpr GestureId kNoGesture = 0;
GestureId newGestureId(); // unique for the process, never kNoGesture

struct PropertyEdit {
    EntityRef entity;
    std::string name;
    scene::PropertyValue value;
    GestureId gesture = kNoGesture;
};

struct AppliedEdit {
    std::shared_ptr<const scene::Scene> scene; // the scene after the edit
    scene::PropertyValue previous;             // for undo
    scene::ChangeKind change = scene::ChangeKind::Restart;
};

util::Result<AppliedEdit> applyEdit(const scene::Scene& scene, const PropertyEdit& edit);

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::editor::PropertyEdit)
