// LightMix A/B (issue 21, docs/lightmix.md): named snapshots of the lighting, and a split view
// over the viewport that wipes between two of them (or the open setup, or a *.wllight on disk).
// Both sides are remixes of the same light-group layers (`wavelit --light-mix`): each frame's
// layers (RenderFrame::layers) are recombined twice, with the weights that turn the rendered
// scene into each side (render::remixWeights), so the two halves converge together and differ
// only where the lighting does. A side that differs in more than weights (a moved light, another
// map) cannot be a remix and is refused with a message saying so.
//
// The view is a transparent child covering the viewport: it paints the composite (A left of the
// wipe line, B right of it) and a vertical line the mouse drags. Widget name "lightMixCompare".
#pragma once

#include "viewport/render_frame.h"

#include "scene/scene.h"
#include "util/result.h"

#include <QImage>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace wavelit::editor {

class LightMixCompare : public QWidget {
    Q_OBJECT
public:
    struct Side {
        QString label;
        scene::LightingSetup lighting;
        std::function<scene::LightingSetup()> live = {}; // set: the lighting now (the open setup)
    };

    explicit LightMixCompare(QWidget* viewport);

    void snapshot(const QString& name, const scene::LightingSetup& lighting);
    std::optional<scene::LightingSetup> snapshotNamed(const QString& name) const;
    QStringList snapshotNames() const;

    // Shows the split view from the next frame on; the sides are checked against each frame's
    // rendered scene. stop() hides it.
    void start(Side a, Side b);
    void stop();
    bool active() const { return m_active; }
    // The wipe line's position, 0 (all B) to 1 (all A), default 0.5.
    void setWipe(double fraction);
    double wipe() const { return m_wipe; }

    // Recomposes from the frame's layers; returns the reason when a side cannot be shown.
    util::Status showFrame(const RenderFrame& frame);
    // The latest frame as shown (tone-mapped; A left of the wipe), and each side's mean
    // luminance over the whole image.
    QImage composite() const;
    std::array<double, 2> sideMeans() const { return m_means; }
    int compositeSamples() const { return m_samples; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    QRect imageRect() const;
    void wipeTo(int x);

    std::map<QString, scene::LightingSetup> m_snapshots;
    std::array<Side, 2> m_sides;
    bool m_active = false;
    double m_wipe = 0.5;
    std::array<QImage, 2> m_images; // each side's remix, tone-mapped
    std::array<double, 2> m_means{0.0, 0.0};
    int m_samples = 0;
};

// The scene side `lighting` shows over `rendered`: the rendered scene with that lighting, its
// environment map taken as the rendered one when both name the same file (a *.wllight on disk
// names it from its own folder). Exposed for tests.
scene::Scene compareSideScene(const scene::Scene& rendered, const scene::LightingSetup& lighting);

} // namespace wavelit::editor
