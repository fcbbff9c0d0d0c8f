#include "panels/property_editors.h"

#include "panels/gesture_tracker.h"

#include "panels/range_guard.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QDir>
#include <QFileDialog>
#include <QPushButton>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>

#include <glm/common.hpp>

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

QDoubleSpinBox* makeSpin(const scene::PropertyInfo& info, QWidget* parent, const EditorContext& context) {
    auto* spin = new TypedDoubleSpinBox(parent);
    guardRange(spin, info, context.refuse);
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

PropertyEditor floatEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent,
                           const EditorContext& context) {
    if (!wantsSlider(info)) {
        auto* spin = makeSpin(info, parent, context);
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
    auto* spin = makeSpin(info, box, context);
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

PropertyEditor intEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent,
                         const EditorContext& context) {
    auto* spin = new TypedSpinBox(parent);
    guardRange(spin, info, context.refuse);
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
                            QWidget* parent, const EditorContext& context) {
    auto* box = new QWidget(parent);
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto spins = std::make_shared<std::vector<QDoubleSpinBox*>>();
    auto* gestures = new GestureTracker(box);
    for (int i = 0; i < components; ++i) {
        auto* spin = makeSpin(info, box, context);
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

// A colour: a swatch that opens QColorDialog; an HDR colour (no upper bound) also has an
// intensity: value = swatch (components in [0, 1], the largest 1) x intensity.
PropertyEditor colorEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent,
                           const EditorContext& context) {
    const bool hdr = info.max > 1.0;
    auto* box = new QWidget(parent);
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    auto* swatch = new QPushButton(box);
    swatch->setObjectName("swatch");
    swatch->setMinimumWidth(48);
    layout->addWidget(swatch, 1);
    QDoubleSpinBox* intensity = nullptr;
    if (hdr) {
        scene::PropertyInfo range = info;
        range.min = 0.0;
        intensity = makeSpin(range, box, context);
        intensity->setObjectName("intensity");
        intensity->setPrefix(QObject::tr("× "));
        intensity->setToolTip(QObject::tr("Intensity: the colour's largest component"));
        layout->addWidget(intensity);
    }
    auto state = std::make_shared<glm::vec3>(0.0f); // the value shown
    auto paint = [swatch, intensity, state, hdr] {
        const float k = hdr ? std::max({state->r, state->g, state->b}) : 1.0f;
        const glm::vec3 c = k > 0.0f ? glm::clamp(*state / k, 0.0f, 1.0f) : glm::vec3(0.0f);
        const QColor color = QColor::fromRgbF(c.r, c.g, c.b);
        swatch->setStyleSheet(QStringLiteral("background-color: %1").arg(color.name()));
        swatch->setText(QStringLiteral("%1 %2 %3").arg(state->r, 0, 'g', 3).arg(state->g, 0, 'g', 3).arg(state->b, 0, 'g', 3));
        if (intensity) {
            const QSignalBlocker block(intensity);
            intensity->setValue(k);
        }
    };
    QObject::connect(swatch, &QPushButton::clicked, box, [box, state, commit, hdr, info] {
        const float k = hdr ? std::max({state->r, state->g, state->b}) : 1.0f;
        const glm::vec3 c = k > 0.0f ? glm::clamp(*state / k, 0.0f, 1.0f) : glm::vec3(1.0f);
        const QColor picked = QColorDialog::getColor(QColor::fromRgbF(c.r, c.g, c.b), box,
                                                     QString::fromStdString(info.label));
        if (!picked.isValid()) return;
        const float scale = hdr ? (k > 0.0f ? k : 1.0f) : 1.0f;
        commit(glm::vec3(picked.redF(), picked.greenF(), picked.blueF()) * scale, kNoGesture);
    });
    if (intensity) {
        GestureTracker* gestures = trackGestures(intensity, {intensity});
        QObject::connect(intensity, &QDoubleSpinBox::valueChanged, box, [state, commit, gestures](double k) {
            const float old = std::max({state->r, state->g, state->b});
            const glm::vec3 c = old > 0.0f ? *state / old : glm::vec3(1.0f);
            commit(c * float(k), gestures->current());
        });
    }
    return {box, [state, paint](const scene::PropertyValue& v) {
                if (auto* c = std::get_if<glm::vec3>(&v)) {
                    *state = *c;
                    paint();
                }
            }};
}

// A path: the text as the file stores it, and "…" to pick a file (made relative to the folder
// the context names for the entity's kind).
PropertyEditor pathEditor(const scene::PropertyInfo& info, CommitValue commit, QWidget* parent,
                          const EditorContext& context) {
    auto* box = new QWidget(parent);
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto* line = new QLineEdit(box);
    line->setObjectName("path");
    auto* browse = new QPushButton(QObject::tr("…"), box);
    browse->setObjectName("browse");
    browse->setToolTip(QObject::tr("Choose a file"));
    layout->addWidget(line, 1);
    layout->addWidget(browse);
    QObject::connect(line, &QLineEdit::editingFinished, line, [line, commit] {
        if (line->isModified()) commit(line->text().toStdString(), kNoGesture);
        line->setModified(false);
    });
    const scene::EntityKind kind = info.entity;
    auto folder = context.folder;
    QObject::connect(browse, &QPushButton::clicked, box, [box, line, commit, folder, kind, info] {
        const QString base = folder ? folder(kind) : QString();
        const QString start = base.isEmpty() ? QString() : QDir(base).filePath(line->text());
        const QString picked = QFileDialog::getOpenFileName(box, QString::fromStdString(info.label), start);
        if (picked.isEmpty()) return;
        const QString stored = base.isEmpty() ? picked : QDir(base).relativeFilePath(picked);
        commit(stored.toStdString(), kNoGesture);
    });
    return {box, [line](const scene::PropertyValue& v) {
                if (auto* s = std::get_if<std::string>(&v)) {
                    const QSignalBlocker block(line);
                    line->setText(QString::fromStdString(*s));
                    line->setModified(false);
                }
            }};
}

} // namespace

PropertyEditor createPropertyEditor(const scene::PropertyInfo& info, const scene::Scene& scene,
                                    CommitValue commit, QWidget* parent, const EditorContext& context) {
    PropertyEditor editor;
    switch (info.type) {
    case scene::PropertyType::Bool: editor = boolEditor(commit, parent); break;
    case scene::PropertyType::Int: editor = intEditor(info, commit, parent, context); break;
    case scene::PropertyType::Float: editor = floatEditor(info, commit, parent, context); break;
    case scene::PropertyType::Vec2: editor = vectorEditor(info, 2, commit, parent, context); break;
    case scene::PropertyType::Vec3: editor = vectorEditor(info, 3, commit, parent, context); break;
    case scene::PropertyType::Color: editor = colorEditor(info, commit, parent, context); break;
    case scene::PropertyType::Enum: editor = enumEditor(info, commit, parent); break;
    case scene::PropertyType::IdRef: editor = idRefEditor(info, scene, commit, parent); break;
    case scene::PropertyType::String: editor = textEditor(commit, parent); break;
    case scene::PropertyType::Path: editor = pathEditor(info, commit, parent, context); break;
    }
    editor.widget->setObjectName(QStringLiteral("edit_") + QString::fromStdString(info.name));
    editor.widget->setToolTip(QString::fromStdString(info.tooltip));
    return editor;
}

} // namespace wavelit::editor
