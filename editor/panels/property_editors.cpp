#include "panels/property_editors.h"

#include "panels/gesture_tracker.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>

#include <algorithm>
#include <cmath>
#include <memory>
#include <variant>

namespace wavelit::editor {
namespace {

// Spin boxes need finite limits; the registry's "unbounded" is +-1e30.
constexpr double kSpinLimit = 1e6;
constexpr int kDecimals = 3;

double spinMin(const scene::PropertyInfo& info) { return std::max(info.min, -kSpinLimit); }
double spinMax(const scene::PropertyInfo& info) { return std::min(info.max, kSpinLimit); }

QDoubleSpinBox* makeSpin(const scene::PropertyInfo& info, QWidget* parent) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setRange(spinMin(info), spinMax(info));
    spin->setDecimals(kDecimals);
    // A bounded range steps in hundredths of itself (roughness 0.01); an open one in 0.1.
    const double span = spinMax(info) - spinMin(info);
    spin->setSingleStep(span <= 10.0 ? span / 100.0 : 0.1);
    spin->setKeyboardTracking(false); // commit on Enter / focus loss / arrows, not per keystroke
    spin->setToolTip(QString::fromStdString(info.tooltip));
    return spin;
}

// The tracker lives as long as the widget it watches.
GestureTracker* trackGestures(QWidget* owner, std::initializer_list<QObject*> watched) {
    auto* tracker = new GestureTracker(owner);
    for (QObject* w : watched) tracker->watch(w);
    return tracker;
}

// A slider beside the spin box for ranges an artist sweeps (roughness, cone angles): finite and
// not wider than kSliderMaxSpan. kSliderSteps positions; the spin box stays exact.
constexpr double kSliderMaxSpan = 1000.0;
constexpr int kSliderSteps = 1000;

bool wantsSlider(const scene::PropertyInfo& info) {
    return info.min > -1e29 && info.max < 1e29 && info.max - info.min <= kSliderMaxSpan;
}

PropertyEditor floatEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent) {
    if (!wantsSlider(info)) {
        auto* spin = makeSpin(info, parent);
        if (!info.unit.empty()) spin->setSuffix(" " + QString::fromStdString(info.unit));
        GestureTracker* gestures = trackGestures(spin, {spin});
        QObject::connect(spin, &QDoubleSpinBox::valueChanged, spin,
                         [commit, gestures](double v) { commit(float(v), gestures->current()); });
        return {spin, [spin](const scene::PropertyValue& v) {
                    if (auto* f = std::get_if<float>(&v)) {
                        const QSignalBlocker block(spin);
                        spin->setValue(*f);
                    }
                }};
    }
    auto* box = new QWidget(parent);
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    auto* slider = new QSlider(Qt::Horizontal, box);
    slider->setObjectName("slider");
    slider->setRange(0, kSliderSteps);
    auto* spin = makeSpin(info, box);
    spin->setObjectName("spin");
    if (!info.unit.empty()) spin->setSuffix(" " + QString::fromStdString(info.unit));
    layout->addWidget(slider, 1);
    layout->addWidget(spin);
    const double lo = spinMin(info), span = spinMax(info) - spinMin(info);
    auto toSlider = [lo, span](double v) { return int(std::lround((v - lo) / span * kSliderSteps)); };
    auto setSliderQuietly = [slider, toSlider](double v) {
        const QSignalBlocker block(slider);
        slider->setValue(toSlider(v));
    };
    GestureTracker* gestures = trackGestures(box, {slider, spin});
    QObject::connect(slider, &QSlider::sliderPressed, gestures, &GestureTracker::begin);
    QObject::connect(slider, &QSlider::sliderReleased, gestures, &GestureTracker::end);
    QObject::connect(slider, &QSlider::valueChanged, spin, [spin, lo, span](int position) {
        spin->setValue(lo + span * double(position) / kSliderSteps); // commits through the spin box
    });
    QObject::connect(spin, &QDoubleSpinBox::valueChanged, box,
                     [commit, gestures, setSliderQuietly](double v) {
                         setSliderQuietly(v);
                         commit(float(v), gestures->current());
                     });
    return {box, [spin, setSliderQuietly](const scene::PropertyValue& v) {
                if (auto* f = std::get_if<float>(&v)) {
                    const QSignalBlocker block(spin);
                    spin->setValue(*f);
                    setSliderQuietly(*f);
                }
            }};
}

PropertyEditor intEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent) {
    auto* spin = new QSpinBox(parent);
    spin->setRange(int(std::max(info.min, -kSpinLimit)), int(std::min(info.max, kSpinLimit)));
    spin->setKeyboardTracking(false);
    if (!info.unit.empty()) spin->setSuffix(" " + QString::fromStdString(info.unit));
    GestureTracker* gestures = trackGestures(spin, {spin});
    QObject::connect(spin, &QSpinBox::valueChanged, spin,
                     [commit, gestures](int v) { commit(v, gestures->current()); });
    return {spin, [spin](const scene::PropertyValue& v) {
                if (auto* i = std::get_if<int>(&v)) {
                    const QSignalBlocker block(spin);
                    spin->setValue(*i);
                }
            }};
}

// Vec2, Vec3 and Color: one spin box per component; any change commits the whole vector.
PropertyEditor vectorEditor(const scene::PropertyInfo& info, int components, CommitValue commit,
                            QWidget* parent) {
    auto* box = new QWidget(parent);
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto spins = std::make_shared<std::vector<QDoubleSpinBox*>>();
    auto* gestures = new GestureTracker(box);
    for (int i = 0; i < components; ++i) {
        auto* spin = makeSpin(info, box);
        spin->setObjectName(QStringLiteral("component%1").arg(i));
        layout->addWidget(spin);
        spins->push_back(spin);
        gestures->watch(spin);
    }
    for (auto* spin : *spins)
        QObject::connect(spin, &QDoubleSpinBox::valueChanged, box, [spins, components, commit, gestures] {
            glm::vec3 v(0.0f);
            for (int i = 0; i < components; ++i) v[i] = float((*spins)[size_t(i)]->value());
            if (components == 2)
                commit(glm::vec2(v.x, v.y), gestures->current());
            else
                commit(v, gestures->current());
        });
    return {box, [spins](const scene::PropertyValue& value) {
                glm::vec3 v(0.0f);
                if (auto* v3 = std::get_if<glm::vec3>(&value)) v = *v3;
                else if (auto* v2 = std::get_if<glm::vec2>(&value)) v = glm::vec3(*v2, 0.0f);
                else return;
                for (size_t i = 0; i < spins->size(); ++i) {
                    const QSignalBlocker block((*spins)[i]);
                    (*spins)[i]->setValue(v[int(i)]);
                }
            }};
}

PropertyEditor boolEditor(CommitValue commit, QWidget* parent) {
    auto* check = new QCheckBox(parent);
    QObject::connect(check, &QCheckBox::toggled, check, [commit](bool on) { commit(on, kNoGesture); });
    return {check, [check](const scene::PropertyValue& v) {
                if (auto* b = std::get_if<bool>(&v)) {
                    const QSignalBlocker block(check);
                    check->setChecked(*b);
                }
            }};
}

PropertyEditor enumEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    for (const auto& option : info.enumOptions) combo->addItem(QString::fromStdString(option));
    QObject::connect(combo, &QComboBox::activated, combo,
                     [combo, commit](int) { commit(combo->currentText().toStdString(), kNoGesture); });
    return {combo, [combo](const scene::PropertyValue& v) {
                if (auto* s = std::get_if<std::string>(&v)) {
                    const QSignalBlocker block(combo);
                    combo->setCurrentText(QString::fromStdString(*s));
                }
            }};
}

PropertyEditor idRefEditor(const scene::PropertyInfo& info, const scene::Scene& scene,
                           CommitValue commit, QWidget* parent) {
    auto* combo = new QComboBox(parent);
    auto add = [combo](const auto& entities) {
        for (const auto& e : entities) combo->addItem(QString::fromStdString(e.name), QVariant::fromValue(e.id));
    };
    switch (info.refersTo) {
    case scene::EntityKind::Material: add(scene.materials); break;
    case scene::EntityKind::Object: add(scene.objects); break;
    case scene::EntityKind::Light: add(scene.lighting.lights); break;
    default: break;
    }
    QObject::connect(combo, &QComboBox::activated, combo, [combo, commit](int index) {
        commit(combo->itemData(index).value<scene::EntityId>(), kNoGesture);
    });
    return {combo, [combo](const scene::PropertyValue& v) {
                if (auto* id = std::get_if<scene::EntityId>(&v)) {
                    const QSignalBlocker block(combo);
                    combo->setCurrentIndex(combo->findData(QVariant::fromValue(*id)));
                }
            }};
}

PropertyEditor textEditor(CommitValue commit, QWidget* parent) {
    auto* line = new QLineEdit(parent);
    QObject::connect(line, &QLineEdit::editingFinished, line, [line, commit] {
        if (line->isModified()) commit(line->text().toStdString(), kNoGesture);
        line->setModified(false);
    });
    return {line, [line](const scene::PropertyValue& v) {
                if (auto* s = std::get_if<std::string>(&v)) {
                    const QSignalBlocker block(line);
                    line->setText(QString::fromStdString(*s));
                    line->setModified(false);
                }
            }};
}

} // namespace

PropertyEditor createPropertyEditor(const scene::PropertyInfo& info, const scene::Scene& scene,
                                    CommitValue commit, QWidget* parent) {
    PropertyEditor editor;
    switch (info.type) {
    case scene::PropertyType::Bool: editor = boolEditor(commit, parent); break;
    case scene::PropertyType::Int: editor = intEditor(info, commit, parent); break;
    case scene::PropertyType::Float: editor = floatEditor(info, commit, parent); break;
    case scene::PropertyType::Vec2: editor = vectorEditor(info, 2, commit, parent); break;
    case scene::PropertyType::Vec3:
    case scene::PropertyType::Color: editor = vectorEditor(info, 3, commit, parent); break;
    case scene::PropertyType::Enum: editor = enumEditor(info, commit, parent); break;
    case scene::PropertyType::IdRef: editor = idRefEditor(info, scene, commit, parent); break;
    case scene::PropertyType::String:
    case scene::PropertyType::Path: editor = textEditor(commit, parent); break;
    }
    editor.widget->setObjectName(QStringLiteral("edit_") + QString::fromStdString(info.name));
    editor.widget->setToolTip(QString::fromStdString(info.tooltip));
    return editor;
}

} // namespace wavelit::editor
