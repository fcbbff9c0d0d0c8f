#include "app/lightmix_compare.h"

#include "lightmix/compare_side_render.h"

#include "viewport/tone_map.h"

#include "render/session/light_groups.h"
#include "render/session/light_remix.h"
#include "scene/scene_compare.h"

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

const char* compareModeName(LightMixCompare::Mode mode) {
    return mode == LightMixCompare::Mode::Remix ? "remix" : "render";
}

LightMixCompare::LightMixCompare(QWidget* viewport) : QWidget(viewport) {
    setObjectName("lightMixCompare");
    setMouseTracking(false);
    hide();
    viewport->installEventFilter(this);
    setGeometry(viewport->rect());
    for (size_t s = 0; s < 2; ++s) {
        m_sides[s].render = new CompareSideRender(this);
        connect(m_sides[s].render, &CompareSideRender::frameReady, this, [this, s] { onSideRenderFrame(s); });
        connect(m_sides[s].render, &CompareSideRender::failed, this, [this, s](const QString& message) {
            emit sideRenderFailed(tr("A/B: the render of '%1' failed: %2").arg(m_sides[s].side.label, message));
        });
    }
}

LightMixCompare::~LightMixCompare() = default;

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

void LightMixCompare::start(Side a, Side b, const scene::Scene& rendered, RenderContext context) {
    stop();
    m_context = std::move(context);
    m_sides[0].side = std::move(a);
    m_sides[1].side = std::move(b);
    m_active = true;
    for (SideState& side : m_sides) choose(side, rendered);
    setGeometry(parentWidget()->rect());
    show();
    raise();
}

void LightMixCompare::stop() {
    m_active = false;
    for (SideState& side : m_sides) {
        side.render->stop();
        side.mode = Mode::Remix;
        side.linear.reset();
        side.image = {};
        side.mean = 0.0;
        side.samples = 0;
    }
    hide();
}

void LightMixCompare::setWipe(double fraction) {
    m_wipe = std::clamp(fraction, 0.0, 1.0);
    update();
}

int LightMixCompare::sideValidationMessages() const {
    return m_sides[0].render->latest().validationMessages + m_sides[1].render->latest().validationMessages;
}

scene::LightingSetup LightMixCompare::lightingOf(const SideState& side) const {
    return side.side.live ? side.side.live() : side.side.lighting;
}

std::optional<std::vector<glm::vec3>> LightMixCompare::choose(SideState& side, const scene::Scene& rendered) {
    scene::Scene shown = compareSideScene(rendered, lightingOf(side));
    if (auto weights = render::remixWeights(rendered, shown)) {
        if (side.mode == Mode::Render) {
            side.render->stop();
            side.linear.reset();
            side.image = {};
        }
        side.mode = Mode::Remix;
        return weights;
    }
    if (side.mode == Mode::Remix) { // the remix's image is not this side's any more
        side.linear.reset();
        side.image = {};
        side.samples = 0;
    }
    side.mode = Mode::Render;
    // Restart only when the scene the side needs changed (an edit of the open scene, a live side
    // edited); a frame of the same scene keeps the side's samples.
    const auto& running = side.render->scene();
    if (!running || !scene::firstDifference(*running, shown).empty()) {
        const render::RenderOptions options = m_context.options ? m_context.options(shown) : render::RenderOptions{};
        side.linear.reset();
        side.image = {};
        side.samples = 0;
        side.render->start(std::make_shared<const scene::Scene>(std::move(shown)), options,
                           m_context.maxSamplesPerPixel, m_context.scenePath);
    }
    return std::nullopt;
}

void LightMixCompare::setLinear(SideState& side, std::shared_ptr<const util::ImageRGB> linear, int samples) {
    side.linear = std::move(linear);
    side.samples = samples;
    side.image = side.linear ? toneMap(*side.linear, m_exposureEv) : QImage();
    double sum = 0.0;
    if (side.linear)
        for (const glm::vec3& p : side.linear->pixels) sum += util::luminance(p);
    side.mean = side.linear && !side.linear->pixels.empty() ? sum / double(side.linear->pixels.size()) : 0.0;
}

void LightMixCompare::onSideRenderFrame(size_t s) {
    SideState& side = m_sides[s];
    if (!m_active || side.mode != Mode::Render) return;
    const CompareSideFrame& frame = side.render->latest();
    setLinear(side, frame.image, frame.samplesPerPixel);
    update();
}

util::Status LightMixCompare::showFrame(const RenderFrame& frame) {
    if (!m_active) return util::okStatus();
    auto fail = [](const QString& why) {
        return util::makeError(util::ErrorKind::Invalid, "", why.toStdString());
    };
    if (!frame.layers || !frame.layersScene || frame.layers->empty())
        return fail(tr("A/B compares remixes of light-group layers: start the editor with --light-mix"));
    const bool exposureChanged = frame.displayExposureEv != m_exposureEv;
    m_exposureEv = frame.displayExposureEv;
    for (SideState& side : m_sides) {
        if (auto weights = choose(side, *frame.layersScene)) {
            setLinear(side, std::make_shared<const util::ImageRGB>(render::mixGroupLayers(*frame.layers, *weights)),
                      frame.samplesPerPixel);
        } else if (exposureChanged && side.linear) {
            setLinear(side, side.linear, side.samples); // re-tone-map the render's latest frame
        }
    }
    update();
    return util::okStatus();
}

QImage LightMixCompare::composite() const {
    const QImage& a = m_sides[0].image;
    const QImage& b = m_sides[1].image;
    if (a.isNull() || b.isNull() || a.size() != b.size()) return {};
    QImage out = b.convertToFormat(QImage::Format_RGB32);
    const int split = int(m_wipe * out.width() + 0.5);
    QPainter painter(&out);
    painter.drawImage(QRect(0, 0, split, out.height()), a, QRect(0, 0, split, out.height()));
    return out;
}

QRect LightMixCompare::imageRect() const {
    const QImage& shown = m_sides[0].image.isNull() ? m_sides[1].image : m_sides[0].image;
    if (shown.isNull()) return rect();
    const QSize fitted = shown.size().scaled(size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
}

bool LightMixCompare::eventFilter(QObject* watched, QEvent* event) {
    if (watched == parentWidget() && event->type() == QEvent::Resize) setGeometry(parentWidget()->rect());
    return QWidget::eventFilter(watched, event);
}

void LightMixCompare::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(40, 40, 40));
    painter.setPen(Qt::white);
    if (m_sides[0].image.isNull() && m_sides[1].image.isNull()) {
        painter.drawText(rect(), Qt::AlignCenter, tr("A/B: waiting for a frame"));
        return;
    }
    const QRect target = imageRect();
    const int x = target.left() + int(m_wipe * target.width() + 0.5);
    // A side without an image yet (its own render has not finished a pass) stays dark.
    auto draw = [&](const SideState& side, const QRect& clip) {
        painter.setClipRect(clip);
        if (side.image.isNull()) {
            painter.drawText(clip, Qt::AlignCenter, tr("rendering…"));
            return;
        }
        painter.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < side.image.width());
        painter.drawImage(target, side.image);
    };
    draw(m_sides[1], QRect(QPoint(x, target.top()), target.bottomRight()));
    draw(m_sides[0], QRect(target.topLeft(), QPoint(x, target.bottom())));
    painter.setClipping(false);
    painter.setPen(QPen(Qt::white, 2));
    painter.drawLine(x, target.top(), x, target.bottom());
    auto caption = [](const SideState& side, const char* which) {
        return QStringLiteral("%1: %2 (%3, %4 spp)")
            .arg(which, side.side.label, compareModeName(side.mode))
            .arg(side.samples);
    };
    painter.drawText(target.adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::AlignTop, caption(m_sides[0], "A"));
    painter.drawText(target.adjusted(6, 4, -6, -4), Qt::AlignRight | Qt::AlignTop, caption(m_sides[1], "B"));
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
