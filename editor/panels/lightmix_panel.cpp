#include "panels/lightmix_panel.h"

#include "panels/gesture_tracker.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <functional>

namespace wavelit::editor {
namespace {

constexpr double kMaxIntensity = 1e6;
constexpr const char* kEnvironmentRow = "environment"; // render::kEnvironmentGroup
constexpr const char* kEmissionRow = "emission";       // render::kEmissionGroup

// render::lightGroupName (the panels do not link the render layer): the group, else the name.
std::string groupNameOf(const scene::Light& light) {
    if (!light.group.empty()) return light.group;
    if (!light.name.empty()) return light.name;
    return "light-" + std::to_string(light.id);
}

bool emits(const glm::vec3& e) { return e.r > 0.0f || e.g > 0.0f || e.b > 0.0f; }

float luminanceOf(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

QString swatchStyle(const glm::vec3& c) {
    auto channel = [](float v) { return int(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
    return QStringLiteral("background-color: rgb(%1, %2, %3); border: 1px solid gray;")
        .arg(channel(c.r))
        .arg(channel(c.g))
        .arg(channel(c.b));
}

// The slider is logarithmic, 1e-3 .. 1e5 over kSliderSteps (intensities span eight decades
// between a dim practical and a sun); its lowest step is 0.
constexpr int kSliderSteps = 800;
constexpr double kSliderLowLog = -3.0, kSliderHighLog = 5.0;

int sliderPosition(double intensity) {
    if (!(intensity > 0.0)) return 0;
    const double t = (std::log10(intensity) - kSliderLowLog) / (kSliderHighLog - kSliderLowLog);
    return std::clamp(int(std::lround(t * kSliderSteps)), 1, kSliderSteps);
}

double sliderIntensity(int position) {
    if (position <= 0) return 0.0;
    return std::pow(10.0, kSliderLowLog + (kSliderHighLog - kSliderLowLog) * double(position) / kSliderSteps);
}

// A colour swatch that opens a colour dialog when clicked. The dialog edits the colour's
// chromaticity and brightness in 0..1; a light's colour is usually normalised to luminance 1
// and the intensity carries the power, so that is all it needs.
class Swatch : public QLabel {
public:
    explicit Swatch(std::function<void(const glm::vec3&)> picked) : m_picked(std::move(picked)) {
        setCursor(Qt::PointingHandCursor);
    }
    glm::vec3 colour{1.0f};

protected:
    void mousePressEvent(QMouseEvent*) override {
        const auto channel = [](float v) { return int(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
        const QColor chosen = QColorDialog::getColor(QColor(channel(colour.r), channel(colour.g), channel(colour.b)),
                                                     this, tr("Group colour"));
        if (chosen.isValid()) m_picked(glm::vec3(chosen.redF(), chosen.greenF(), chosen.blueF()));
    }

private:
    std::function<void(const glm::vec3&)> m_picked;
};

QDoubleSpinBox* intensityBox(const QString& objectName) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(objectName);
    box->setRange(0.0, kMaxIntensity);
    box->setDecimals(3);
    box->setKeyboardTracking(false); // one edit per value, not per key
    return box;
}

QSlider* intensitySlider(const QString& objectName, GestureTracker* gestures) {
    auto* slider = new QSlider(Qt::Horizontal);
    slider->setObjectName(objectName);
    slider->setRange(0, kSliderSteps);
    slider->setToolTip(QObject::tr("Intensity, logarithmic (0.001 to 100000)"));
    gestures->watch(slider);
    QObject::connect(slider, &QSlider::sliderPressed, gestures, &GestureTracker::begin);
    QObject::connect(slider, &QSlider::sliderReleased, gestures, &GestureTracker::end);
    return slider;
}

} // namespace

std::vector<LightMixRow> lightMixRows(const scene::Scene& scene) {
    std::vector<LightMixRow> rows;
    LightMixRow environment{LightMixRow::Kind::Environment, kEnvironmentRow, {}, {}};
    LightMixRow emission{LightMixRow::Kind::Emission, kEmissionRow, {}, {}};
    for (const scene::Light& l : scene.lighting.lights) {
        const std::string name = groupNameOf(l);
        if (name == kEnvironmentRow) {
            environment.lights.push_back(l.id);
            continue;
        }
        if (name == kEmissionRow) {
            emission.lights.push_back(l.id);
            continue;
        }
        auto it = std::find_if(rows.begin(), rows.end(), [&](const LightMixRow& r) { return r.name == name; });
        if (it == rows.end()) rows.push_back({LightMixRow::Kind::Lights, name, {l.id}, {}});
        else it->lights.push_back(l.id);
    }
    rows.push_back(std::move(environment));
    for (const scene::Object& object : scene.objects) {
        const scene::Material* m = scene.findMaterial(object.materialId);
        if (m && emits(m->emission) &&
            std::find(emission.materials.begin(), emission.materials.end(), m->id) == emission.materials.end())
            emission.materials.push_back(m->id);
    }
    if (!emission.materials.empty()) rows.push_back(std::move(emission));
    return rows;
}

LightMixPanel::LightMixPanel(QWidget* parent)
    : QWidget(parent), m_grid(new QGridLayout(this)), m_gestures(new GestureTracker(this)) {
    setObjectName("lightMixPanel");
}

void LightMixPanel::setScene(const scene::Scene& scene) {
    m_scene = scene;
    std::vector<LightMixRow> rows = lightMixRows(scene);
    // Muted emission has no layer while it is 0: its row stays so it can be unmuted.
    const bool emissionRow = std::any_of(rows.begin(), rows.end(),
                                         [](const LightMixRow& r) { return r.kind == LightMixRow::Kind::Emission; });
    if (!emissionRow && !m_emissionBeforeMute.empty()) {
        LightMixRow emission{LightMixRow::Kind::Emission, kEmissionRow, {}, {}};
        for (const auto& [id, value] : m_emissionBeforeMute)
            if (scene.findMaterial(id)) emission.materials.push_back(id);
        if (!emission.materials.empty()) rows.push_back(std::move(emission));
    }
    auto same = [](const LightMixRow& a, const LightMixRow& b) {
        return a.kind == b.kind && a.name == b.name && a.lights == b.lights && a.materials == b.materials;
    };
    const bool changed = rows.size() != m_rows.size() || !std::equal(rows.begin(), rows.end(), m_rows.begin(), same);
    m_rows = std::move(rows);
    if (changed || m_grid->count() == 0) rebuild();
    refresh();
}

double LightMixPanel::rowIntensity(const LightMixRow& row) const {
    if (row.kind == LightMixRow::Kind::Environment) return m_scene.lighting.environment.intensity;
    if (row.kind == LightMixRow::Kind::Emission) {
        for (scene::EntityId id : row.materials)
            if (const scene::Material* m = m_scene.findMaterial(id); m && emits(m->emission))
                return luminanceOf(m->emission);
        return 0.0;
    }
    for (scene::EntityId id : row.lights)
        if (const scene::Light* l = m_scene.findLight(id); l && l->intensity > 0.0f) return l->intensity;
    return 0.0;
}

glm::vec3 LightMixPanel::rowColour(const LightMixRow& row) const {
    if (row.kind == LightMixRow::Kind::Environment) return m_scene.lighting.environment.tint;
    if (row.kind == LightMixRow::Kind::Emission) {
        for (scene::EntityId id : row.materials)
            if (const scene::Material* m = m_scene.findMaterial(id); m && emits(m->emission))
                return m->emission / std::max({m->emission.r, m->emission.g, m->emission.b});
        return glm::vec3(1.0f);
    }
    const scene::Light* first = row.lights.empty() ? nullptr : m_scene.findLight(row.lights.front());
    return first ? first->color : glm::vec3(1.0f);
}

bool LightMixPanel::rowMuted(const LightMixRow& row) const {
    if (row.kind == LightMixRow::Kind::Environment) return m_scene.lighting.environment.intensity == 0.0f;
    if (row.kind == LightMixRow::Kind::Emission)
        return std::none_of(row.materials.begin(), row.materials.end(), [&](scene::EntityId id) {
            const scene::Material* m = m_scene.findMaterial(id);
            return m && emits(m->emission);
        });
    return !row.lights.empty() && std::all_of(row.lights.begin(), row.lights.end(), [&](scene::EntityId id) {
        const scene::Light* l = m_scene.findLight(id);
        return l && l->muted;
    });
}

// Every member times intensity / rowIntensity (one factor); a row at 0 is set to `intensity`.
std::vector<LightMixPanel::Target> LightMixPanel::scaled(const LightMixRow& row, double intensity) const {
    const double reference = rowIntensity(row);
    const float factor = reference > 0.0 ? float(intensity / reference) : 1.0f;
    auto value = [&](float current) { return reference > 0.0 ? current * factor : float(intensity); };
    std::vector<Target> targets;
    for (scene::EntityId id : row.lights)
        if (const scene::Light* l = m_scene.findLight(id))
            targets.push_back({{EntityKind::Light, id}, "intensity", value(l->intensity)});
    if (row.kind == LightMixRow::Kind::Environment)
        targets.push_back({{EntityKind::Environment, scene::kInvalidId}, "intensity",
                           value(m_scene.lighting.environment.intensity)});
    if (row.kind == LightMixRow::Kind::Emission && reference > 0.0)
        for (scene::EntityId id : row.materials)
            if (const scene::Material* m = m_scene.findMaterial(id))
                targets.push_back({{EntityKind::Material, id}, "emission", m->emission * factor});
    return targets;
}

// Every member's colour times colour / rowColour, per channel (a channel shown as 0 is set).
std::vector<LightMixPanel::Target> LightMixPanel::tinted(const LightMixRow& row, const glm::vec3& colour) const {
    const glm::vec3 shown = rowColour(row);
    auto apply = [&](const glm::vec3& current) {
        glm::vec3 out;
        for (int c = 0; c < 3; ++c) out[c] = shown[c] > 0.0f ? current[c] * (colour[c] / shown[c]) : colour[c];
        return out;
    };
    std::vector<Target> targets;
    for (scene::EntityId id : row.lights)
        if (const scene::Light* l = m_scene.findLight(id))
            targets.push_back({{EntityKind::Light, id}, "color", apply(l->color)});
    if (row.kind == LightMixRow::Kind::Environment)
        targets.push_back({{EntityKind::Environment, scene::kInvalidId}, "tint", colour});
    if (row.kind == LightMixRow::Kind::Emission)
        for (scene::EntityId id : row.materials)
            if (const scene::Material* m = m_scene.findMaterial(id); m && emits(m->emission))
                targets.push_back({{EntityKind::Material, id}, "emission", apply(m->emission)});
    return targets;
}

std::vector<LightMixPanel::Target> LightMixPanel::muted(const LightMixRow& row, bool on) {
    std::vector<Target> targets;
    for (scene::EntityId id : row.lights)
        if (const scene::Light* l = m_scene.findLight(id); l && l->muted != on)
            targets.push_back({{EntityKind::Light, id}, "muted", on});
    if (row.kind == LightMixRow::Kind::Environment) {
        const float now = m_scene.lighting.environment.intensity;
        if (on && now > 0.0f) {
            m_environmentBeforeMute = now;
            targets.push_back({{EntityKind::Environment, scene::kInvalidId}, "intensity", 0.0f});
        } else if (!on && now == 0.0f) {
            targets.push_back({{EntityKind::Environment, scene::kInvalidId}, "intensity",
                               m_environmentBeforeMute.value_or(1.0f)});
        }
    }
    if (row.kind == LightMixRow::Kind::Emission) {
        for (scene::EntityId id : row.materials) {
            const scene::Material* m = m_scene.findMaterial(id);
            if (!m) continue;
            if (on && emits(m->emission)) {
                m_emissionBeforeMute[id] = m->emission;
                targets.push_back({{EntityKind::Material, id}, "emission", glm::vec3(0.0f)});
            } else if (!on && !emits(m->emission)) {
                auto it = m_emissionBeforeMute.find(id);
                if (it != m_emissionBeforeMute.end())
                    targets.push_back({{EntityKind::Material, id}, "emission", it->second});
            }
        }
        if (!on) m_emissionBeforeMute.clear();
    }
    return targets;
}

void LightMixPanel::solo(const LightMixRow& soloed) {
    std::vector<Target> targets;
    for (const LightMixRow& row : m_rows) {
        std::vector<Target> more = muted(row, row.name != soloed.name);
        targets.insert(targets.end(), more.begin(), more.end());
    }
    emitTargets(targets, tr("solo %1").arg(QString::fromStdString(soloed.name)), kNoGesture);
}

void LightMixPanel::emitTargets(const std::vector<Target>& targets, const QString& text, GestureId gesture) {
    if (targets.empty()) return;
    if (targets.size() == 1) {
        emit editRequested({targets.front().entity, targets.front().property, targets.front().value, gesture});
        return;
    }
    scene::ChangeSet changes;
    for (const Target& t : targets)
        if (auto status = changes.setProperty(m_scene, t.entity, t.property, t.value); !status) return;
    emit groupEditRequested(changes, text, gesture);
}

void LightMixPanel::rebuild() {
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    int gridRow = 0;
    for (const LightMixRow& row : m_rows) {
        const QString name = QString::fromStdString(row.name);
        const std::string key = row.name; // rows are found again by name (m_rows is rebuilt)
        auto findRow = [this, key]() -> const LightMixRow* {
            auto it = std::find_if(m_rows.begin(), m_rows.end(), [&](const LightMixRow& r) { return r.name == key; });
            return it == m_rows.end() ? nullptr : &*it;
        };
        auto* mute = new QCheckBox(tr("mute"));
        mute->setObjectName("mute:" + name);
        connect(mute, &QCheckBox::toggled, this, [this, findRow, name](bool on) {
            if (const LightMixRow* r = findRow())
                emitTargets(muted(*r, on), (on ? tr("mute %1") : tr("unmute %1")).arg(name), kNoGesture);
        });
        auto* soloButton = new QToolButton;
        soloButton->setObjectName("solo:" + name);
        soloButton->setText(tr("S"));
        soloButton->setToolTip(tr("Solo: silence every other group"));
        connect(soloButton, &QToolButton::clicked, this, [this, findRow] {
            if (const LightMixRow* r = findRow()) solo(*r);
        });
        QString label = name;
        if (row.lights.size() > 1) label += tr(" (%1 lights)").arg(row.lights.size());
        auto* title = new QLabel(label);
        title->setObjectName("label:" + name);
        auto* intensity = intensityBox("intensity:" + name);
        connect(intensity, &QDoubleSpinBox::valueChanged, this, [this, findRow, name](double v) {
            if (const LightMixRow* r = findRow()) emitTargets(scaled(*r, v), tr("%1 intensity").arg(name), kNoGesture);
        });
        auto* slider = intensitySlider("slider:" + name, m_gestures);
        connect(slider, &QSlider::valueChanged, this, [this, findRow, name, slider](int position) {
            const LightMixRow* r = findRow();
            if (!r) return;
            // A drag is one gesture (one undo step); other slider moves (keys, wheel) are steps of
            // their own, so a group's step never waits for a release that does not come.
            const GestureId gesture = slider->isSliderDown() ? m_gestures->current() : kNoGesture;
            emitTargets(scaled(*r, sliderIntensity(position)), tr("%1 intensity").arg(name), gesture);
        });
        connect(slider, &QSlider::sliderReleased, this, &LightMixPanel::groupGestureEnded);
        auto* swatch = new Swatch([this, findRow, name](const glm::vec3& c) {
            if (const LightMixRow* r = findRow()) emitTargets(tinted(*r, c), tr("%1 colour").arg(name), kNoGesture);
        });
        swatch->setObjectName("swatch:" + name);
        swatch->setFixedSize(18, 18);
        swatch->setToolTip(tr("Click to change the colour"));
        m_grid->addWidget(mute, gridRow, 0);
        m_grid->addWidget(soloButton, gridRow, 1);
        m_grid->addWidget(title, gridRow, 2);
        m_grid->addWidget(slider, gridRow, 3);
        m_grid->addWidget(intensity, gridRow, 4);
        m_grid->addWidget(swatch, gridRow, 5);
        ++gridRow;
    }
    m_grid->setRowStretch(gridRow, 1);
}

void LightMixPanel::refresh() {
    for (const LightMixRow& row : m_rows) {
        const QString name = QString::fromStdString(row.name);
        const double intensity = rowIntensity(row);
        if (auto* mute = findChild<QCheckBox*>("mute:" + name)) {
            const QSignalBlocker quiet(mute);
            mute->setChecked(rowMuted(row));
        }
        if (auto* box = findChild<QDoubleSpinBox*>("intensity:" + name)) {
            const QSignalBlocker quiet(box);
            box->setValue(intensity);
        }
        if (auto* slider = findChild<QSlider*>("slider:" + name); slider && !slider->isSliderDown()) {
            const QSignalBlocker quiet(slider);
            slider->setValue(sliderPosition(intensity));
        }
        if (auto* swatch = findChild<QLabel*>("swatch:" + name)) {
            swatch->setStyleSheet(swatchStyle(rowColour(row)));
            static_cast<Swatch*>(swatch)->colour = rowColour(row);
        }
    }
}

} // namespace wavelit::editor
