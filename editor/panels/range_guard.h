// guardRange: a spin box refuses a typed value outside the registry's range out loud. Qt's spin
// boxes silently put such text back to the previous value (or clamp it); the artist would not
// know why 1.5 became 1. The guard reads the text when it is committed (Enter, focus leaving),
// and if it is a number outside [min, max] calls `refuse` with a message naming the property,
// the value and the range ("Roughness: 1.5 is outside [0, 1]"); the spin box then keeps its
// previous value as usual, and no edit is sent. Qt's spin boxes also refuse the keystroke that
// would take the text out of range (the "5" of "1.5" never appears), so the editors use the spin
// boxes below, which let any number be typed and leave the refusal to the guard.
#pragma once

#include "scene/property_registry.h"

#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QString>

#include <functional>

namespace wavelit::editor {

class TypedDoubleSpinBox : public QDoubleSpinBox {
public:
    using QDoubleSpinBox::QDoubleSpinBox;
    QValidator::State validate(QString& text, int& pos) const override;
};

class TypedSpinBox : public QSpinBox {
public:
    using QSpinBox::QSpinBox;
    QValidator::State validate(QString& text, int& pos) const override;
};

// The message for `value` outside info's range; empty when inside.
QString rangeRefusal(const scene::PropertyInfo& info, double value);

void guardRange(QAbstractSpinBox* spin, const scene::PropertyInfo& info,
                std::function<void(const QString&)> refuse);

} // namespace wavelit::editor
