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

#include <algorithm>
#include <cmath>
#include <functional>

namespace wavelit::editor {
namespace {

constexpr double kMaxIntensity = 1e6;

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
                                                     this, tr("Light colour"));
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

LightMixPanel::LightMixPanel(QWidget* parent)
    : QWidget(parent), m_grid(new QGridLayout(this)), m_gestures(new GestureTracker(this)) {
    setObjectName("lightMixPanel");
}

void LightMixPanel::setScene(const scene::Scene& scene) {
    std::vector<std::pair<scene::EntityId, std::string>> rows;
    for (const scene::Light& l : scene.lighting.lights) rows.emplace_back(l.id, l.name);
    if (rows != m_rows || m_grid->count() == 0) {
        m_rows = std::move(rows);
        rebuild(scene);
    }
    update(scene);
}

void LightMixPanel::rebuild(const scene::Scene& scene) {
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    int row = 0;
    for (const scene::Light& l : scene.lighting.lights) {
        const QString name = QString::fromStdString(l.name);
        const EntityRef ref{scene::EntityKind::Light, l.id};
        auto* mute = new QCheckBox(tr("mute"));
        mute->setObjectName("mute:" + name);
        connect(mute, &QCheckBox::toggled, this,
                [this, ref](bool on) { emit editRequested({ref, "muted", on}); });
        const QString group = l.group.empty() ? QString() : " (" + QString::fromStdString(l.group) + ")";
        auto* intensity = intensityBox("intensity:" + name);
        connect(intensity, &QDoubleSpinBox::valueChanged, this,
                [this, ref](double v) { emit editRequested({ref, "intensity", float(v)}); });
        auto* slider = intensitySlider("slider:" + name, m_gestures);
        connect(slider, &QSlider::valueChanged, this, [this, ref](int position) {
            emit editRequested({ref, "intensity", float(sliderIntensity(position)), m_gestures->current()});
        });
        auto* swatch = new Swatch([this, ref](const glm::vec3& c) { emit editRequested({ref, "color", c}); });
        swatch->setObjectName("swatch:" + name);
        swatch->setFixedSize(18, 18);
        swatch->setToolTip(tr("Click to change the colour"));
        m_grid->addWidget(mute, row, 0);
        m_grid->addWidget(new QLabel(name + group), row, 1);
        m_grid->addWidget(slider, row, 2);
        m_grid->addWidget(intensity, row, 3);
        m_grid->addWidget(swatch, row, 4);
        ++row;
    }
    const EntityRef env{scene::EntityKind::Environment, scene::kInvalidId};
    auto* envIntensity = intensityBox("intensity:environment");
    connect(envIntensity, &QDoubleSpinBox::valueChanged, this,
            [this, env](double v) { emit editRequested({env, "intensity", float(v)}); });
    auto* envSlider = intensitySlider("slider:environment", m_gestures);
    connect(envSlider, &QSlider::valueChanged, this, [this, env](int position) {
        emit editRequested({env, "intensity", float(sliderIntensity(position)), m_gestures->current()});
    });
    m_grid->addWidget(new QLabel(tr("environment")), row, 1);
    m_grid->addWidget(envSlider, row, 2);
    m_grid->addWidget(envIntensity, row, 3);
    m_grid->setRowStretch(row + 1, 1);
}

void LightMixPanel::update(const scene::Scene& scene) {
    for (const scene::Light& l : scene.lighting.lights) {
        const QString name = QString::fromStdString(l.name);
        if (auto* mute = findChild<QCheckBox*>("mute:" + name)) {
            const QSignalBlocker quiet(mute);
            mute->setChecked(l.muted);
        }
        if (auto* intensity = findChild<QDoubleSpinBox*>("intensity:" + name)) {
            const QSignalBlocker quiet(intensity);
            intensity->setValue(l.intensity);
        }
        if (auto* slider = findChild<QSlider*>("slider:" + name)) {
            const QSignalBlocker quiet(slider);
            slider->setValue(sliderPosition(l.intensity));
        }
        if (auto* swatch = findChild<QLabel*>("swatch:" + name)) {
            swatch->setStyleSheet(swatchStyle(l.color));
            static_cast<Swatch*>(swatch)->colour = l.color;
        }
    }
    if (auto* env = findChild<QDoubleSpinBox*>("intensity:environment")) {
        const QSignalBlocker quiet(env);
        env->setValue(scene.lighting.environment.intensity);
    }
    if (auto* slider = findChild<QSlider*>("slider:environment")) {
        const QSignalBlocker quiet(slider);
        slider->setValue(sliderPosition(scene.lighting.environment.intensity));
    }
}

} // namespace wavelit::editor
