// Editor widgets for one registry property, chosen by PropertyType (not per property): spin boxes
// with the registry's range and unit, a check box, a combo box for enums and entity references, a
// line edit for strings and paths. A widget reports a finished edit through `commit`, and
// `show` refreshes it in place from a new value without emitting (so an undo, or the edit
// itself coming back from the document, never loops or destroys the widget that sent it).
#pragma once

#include "scene/property_registry.h"

#include <functional>

class QWidget;

namespace wavelit::editor {

struct PropertyEditor {
    QWidget* widget = nullptr;
    std::function<void(const scene::PropertyValue&)> show;
};

using CommitValue = std::function<void(const scene::PropertyValue&)>;

// `scene` supplies the choices of IdRef properties (e.g. the material names).
PropertyEditor createPropertyEditor(const scene::PropertyInfo& info, const scene::Scene& scene,
                                    CommitValue commit, QWidget* parent);

} // namespace wavelit::editor
