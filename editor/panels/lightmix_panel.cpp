#include "panels/lightmix_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>

#include <algorithm>

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

QDoubleSpinBox* intensityBox(const QString& objectName) {
    auto* box = new QDoubleSpinBox;
    box->setObjectName(objectName);
    box->setRange(0.0, kMaxIntensity);
    box->setDecimals(3);
    box->setKeyboardTracking(false); // one edit per value, not per key
    return box;
}

} // namespace

LightMixPanel::LightMixPanel(QWidget* parent) : QWidget(parent), m_grid(new QGridLayout(this)) {
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
        auto* swatch = new QLabel;
        swatch->setObjectName("swatch:" + name);
        swatch->setFixedSize(18, 18);
        m_grid->addWidget(mute, row, 0);
        m_grid->addWidget(new QLabel(name + group), row, 1);
        m_grid->addWidget(intensity, row, 2);
        m_grid->addWidget(swatch, row, 3);
        ++row;
    }
    const EntityRef env{scene::EntityKind::Environment, scene::kInvalidId};
    auto* envIntensity = intensityBox("intensity:environment");
    connect(envIntensity, &QDoubleSpinBox::valueChanged, this,
            [this, env](double v) { emit editRequested({env, "intensity", float(v)}); });
    m_grid->addWidget(new QLabel(tr("environment")), row, 1);
    m_grid->addWidget(envIntensity, row, 2);
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
        if (auto* swatch = findChild<QLabel*>("swatch:" + name))
            swatch->setStyleSheet(swatchStyle(l.color));
    }
    if (auto* env = findChild<QDoubleSpinBox*>("intensity:environment")) {
        const QSignalBlocker quiet(env);
        env->setValue(scene.lighting.environment.intensity);
    }
}

} // namespace wavelit::editor
