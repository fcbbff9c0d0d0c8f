// guardRange: a spin box refuses a typed value outside the registry's range out loud. Qt's spin
// boxes silently put such text back to the previous value (or clamp it); the artist would not
// know why 1.5 became 1. The guard reads the text when it is committed (Enter, focus leaving),
// and if it is a number outside [min, max] calls `refuse` with a message naming the property,
// the value and the range ("Roughness: 1.5 is outside [0, 1]"); the spin box then keeps its
// previous value as usual, and no edit is sent.
#pragma once

#include "scene/property_registry.h"

#include <QString>

#include <functional>

class QAbstractSpinBox;

namespace wavelit::editor {

// The message for `value` outside info's range; empty when inside.
QString rangeRefusal(const scene::PropertyInfo& info, double value);

void guardRange(QAbstractSpinBox* spin, const scene::PropertyInfo& info,
                std::function<void(const QString&)> refuse);

} // namespace wavelit::editor
