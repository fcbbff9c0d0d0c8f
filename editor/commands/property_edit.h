// PropertyEdit: one property change as the UI makes it (entity, property, new value, gesture).
// applyEdit turns it into a scene::ChangeSet against the current scene (old and new value: the
// unit the undo stack and the render thread carry, architecture.md §5.B, §9 "Threads"), applies
// that to a scene copy (meshes and images are shared, so a copy is cheap) and says what the edit
// costs: a Display edit (exposure) only re-tone-maps, Restart/Rebuild edits go to the render
// thread with their change set, which updates only what it invalidates.
#pragma once

#include "panels/entity_ref.h"

#include "scene/change_set.h"
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
    scene::ChangeSet changes; // the edit from the given scene to `scene`
};

util::Result<AppliedEdit> applyEdit(const scene::Scene& scene, const PropertyEdit& edit);

} // namespace wavelit::editor

Q_DECLARE_METATYPE(wavelit::editor::PropertyEdit)
