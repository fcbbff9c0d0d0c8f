// Editor widgets for one registry property, chosen by PropertyType (not per property): spin boxes
// with the registry's range and unit, a check box, a combo box for enums and entity references, a
// line edit for strings and paths; a bounded float (roughness, an angle) also gets a slider. A
// widget reports an edit through `commit` with the gesture it belongs to (panels/gesture_tracker.h:
// the values of one slider drag or spin-box scrub share one GestureId), and
// `show` refreshes it in place from a new value without emitting (so an undo, or the edit
// itself coming back from the document, never loops or destroys the widget that sent it).
#pragma once

#include "commands/property_edit.h"
#include "scene/property_registry.h"

#include <functional>

class QWidget;

namespace wavelit::editor {

struct PropertyEditor {
    QWidget* widget = nullptr;
    std::function<void(const scene::PropertyValue&)> show;
};

using CommitValue = std::function<void(const scene::PropertyValue&, GestureId)>;

// `scene` supplies the choices of IdRef properties (e.g. the material names).
PropertyEditor createPropertyEditor(const scene::PropertyInfo& info, const scene::Scene& scene,
                                    CommitValue commit, QWidget* parent);

} // namespace wavelit::editor
