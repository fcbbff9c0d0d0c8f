#include "app/lightmix_compare.h"

#include "viewport/tone_map.h"

#include "render/session/light_groups.h"
#include "render/session/light_remix.h"

#include <QEvent>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>

namespace wavelit::editor {

scene::Scene compareSideScene(const scene::Scene& rendered, const scene::LightingSetup& lighting) {
    scene::Scene shown = rendered;
    shown.lighting = lighting;
    // Only weights may differ: the rest of the environment is the rendered one when the maps
    // are one image (snapshots share it; a setup from disk loaded its own copy of the same file).
    scene::Environment& env = shown.lighting.environment;
    const scene::Environment& base = rendered.lighting.environment;
    const bool sameImage = env.image == base.image ||
                           (env.image && base.image && env.image->pixels == base.image->pixels);
    if (sameImage) {
        env.path = base.path;
        env.image = base.image;
    }
    return shown;
}

LightMixCompare::LightMixCompare(QWidget* viewport) : QWidget(viewport) {
    setObjectName("lightMixCompare");
    setMouseTracking(false);
    hide();
    viewport->installEventFilter(this);
    setGeometry(viewport->rect());
}

void LightMixCompare::snapshot(const QString& name, const scene::LightingSetup& lighting) {
    m_snapshots[name] = lighting;
}

std::optional<scene::LightingSetup> LightMixCompare::snapshotNamed(const QString& name) const {
    auto it = m_snapshots.find(name);
    if (it == m_snapshots.end()) return std::nullopt;
    return it->second;
}

QStringList LightMixCompare::snapshotNames() const {
    QStringList names;
    for (const auto& [name, lighting] : m_snapshots) names << name;
    return names;
}

void LightMixCompare::start(Side a, Side b) {
    m_sides = {std::move(a), std::move(b)};
    m_active = true;
    m_images = {};
    m_samples = 0;
    setGeometry(parentWidget()->rect());
    show();
    raise();
}

void LightMixCompare::stop() {
    m_active = false;
    m_images = {};
    hide();
}

void LightMixCompare::setWipe(double fraction) {
    m_wipe = std::clamp(fraction, 0.0, 1.0);
    update();
}

util::Status LightMixCompare::showFrame(const RenderFrame& frame) {
    if (!m_active) return util::okStatus();
    auto fail = [](const QString& why) {
        return util::makeError(util::ErrorKind::Invalid, "", why.toStdString());
    };
    if (!frame.layers || !frame.layersScene || frame.layers->empty())
        return fail(tr("A/B compares remixes of light-group layers: start the editor with --light-mix"));
    std::array<util::ImageRGB, 2> mixed;
    for (size_t s = 0; s < 2; ++s) {
        const scene::Scene shown = compareSideScene(
            *frame.layersScene, m_sides[s].live ? m_sides[s].live() : m_sides[s].lighting);
        auto weights = render::remixWeights(*frame.layersScene, shown);
        if (!weights)
            return fail(tr("A/B: '%1' differs from the rendered lighting in more than intensities, colours and "
                           "mutes (lights added, moved or retyped, another map, a tint); it needs its own render")
                            .arg(m_sides[s].label));
        mixed[s] = render::mixGroupLayers(*frame.layers, *weights);
        double sum = 0.0;
        for (const glm::vec3& p : mixed[s].pixels) sum += util::luminance(p);
        m_means[s] = mixed[s].pixels.empty() ? 0.0 : sum / double(mixed[s].pixels.size());
    }
    m_images = {toneMap(mixed[0], frame.displayExposureEv), toneMap(mixed[1], frame.displayExposureEv)};
    m_samples = frame.samplesPerPixel;
    update();
    return util::okStatus();
}

QImage LightMixCompare::composite() const {
    if (m_images[0].isNull()) return {};
    QImage out = m_images[1].convertToFormat(QImage::Format_RGB32);
    const int split = int(m_wipe * out.width() + 0.5);
    QPainter painter(&out);
    painter.drawImage(QRect(0, 0, split, out.height()), m_images[0], QRect(0, 0, split, out.height()));
    return out;
}

QRect LightMixCompare::imageRect() const {
    if (m_images[0].isNull()) return rect();
    const QSize fitted = m_images[0].size().scaled(size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
}

bool LightMixCompare::eventFilter(QObject* watched, QEvent* event) {
    if (watched == parentWidget() && event->type() == QEvent::Resize) setGeometry(parentWidget()->rect());
    return QWidget::eventFilter(watched, event);
}

void LightMixCompare::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(40, 40, 40));
    if (m_images[0].isNull()) {
        painter.setPen(Qt::white);
        painter.drawText(rect(), Qt::AlignCenter, tr("A/B: waiting for a frame"));
        return;
    }
    const QRect target = imageRect();
    const int x = target.left() + int(m_wipe * target.width() + 0.5);
    painter.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < m_images[0].width());
    painter.drawImage(target, m_images[1]);
    painter.setClipRect(QRect(target.topLeft(), QPoint(x, target.bottom())));
    painter.drawImage(target, m_images[0]);
    painter.setClipping(false);
    painter.setPen(QPen(Qt::white, 2));
    painter.drawLine(x, target.top(), x, target.bottom());
    painter.drawText(target.adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::AlignTop, "A: " + m_sides[0].label);
    painter.drawText(target.adjusted(6, 4, -6, -4), Qt::AlignRight | Qt::AlignTop, "B: " + m_sides[1].label);
}

void LightMixCompare::wipeTo(int x) {
    const QRect target = imageRect();
    if (target.width() > 0) setWipe(double(x - target.left()) / double(target.width()));
}

void LightMixCompare::mousePressEvent(QMouseEvent* event) { wipeTo(int(event->position().x())); }

void LightMixCompare::mouseMoveEvent(QMouseEvent* event) {
    if (event->buttons() & Qt::LeftButton) wipeTo(int(event->position().x()));
}

} // namespace wavelit::editor
