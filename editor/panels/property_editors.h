// Editor widgets for one registry property, chosen by PropertyType (not per property): spin boxes
// with the registry's range and unit, a check box, a combo box for enums (the BRDF's options are
// the plugin registry's names) and entity references, a line edit for strings, a line edit with
// a "…" file dialog for paths, a colour swatch (QColorDialog) for colours — with an intensity
// spin box beside it when the colour is HDR (unbounded: emission, a light's colour), the value
// being swatch colour x intensity; a bounded float (roughness, an angle) also gets a slider. A
// value typed outside the registry's range is refused with a message through `refuse` (the spin
// box keeps its previous value: never a silent clamp). A
// widget reports an edit through `commit` with the gesture it belongs to (panels/gesture_tracker.h:
// the values of one slider drag or spin-box scrub share one GestureId), and
// `show` refreshes it in place from a new value without emitting (so an undo, or the edit
// itself coming back from the document, never loops or destroys the widget that sent it).
#pragma once

#include "commands/property_edit.h"
#include "scene/property_registry.h"

#include <QString>

#include <functional>

class QWidget;

namespace wavelit::editor {

struct PropertyEditor {
    QWidget* widget = nullptr;
    std::function<void(const scene::PropertyValue&)> show;
};

using CommitValue = std::function<void(const scene::PropertyValue&, GestureId)>;

// What an editor needs beyond the property: where refusals are shown, and the folder a picked
// file's path is made relative to (paths in files are relative, architecture.md §6).
struct EditorContext {
    std::function<void(const QString&)> refuse;      // "Roughness: 1.5 is outside [0, 1]"
    std::function<QString(scene::EntityKind)> folder; // empty or "": the path is kept absolute
};

// `scene` supplies the choices of IdRef properties (e.g. the material names).
PropertyEditor createPropertyEditor(const scene::PropertyInfo& info, const scene::Scene& scene,
                                    CommitValue commit, QWidget* parent, const EditorContext& context = {});

} // namespace wavelit::editor
