// LightMix A/B (issue 21, docs/lightmix.md): named snapshots of the lighting, and a split view
// over the viewport that wipes between two of them (or the open setup, or a *.wllight on disk).
// Each side is shown one of two ways, chosen at every frame:
//   - remix: the side differs from the rendered scene only in light-group weights (intensities,
//     colours, mutes, the environment's intensity; render::remixWeights), so it is the frame's
//     light-group layers (RenderFrame::layers, `wavelit --light-mix`) recombined with its weights
//     and converges together with the viewport's render, from the same samples;
//   - render: anything else differs (a light moved, added or removed, another map, rotation or
//     tint, ...): the side gets its own progressive render of the rendered scene with its
//     lighting (lightmix/compare_side_render.h, a second session on its own thread, at the
//     viewport's size and options), restarted when that scene changes and stopped when the side
//     becomes a remix again or the compare ends.
//
// The view is a transparent child covering the viewport: it paints the composite (A left of the
// wipe line, B right of it) and a vertical line the mouse drags. Widget name "lightMixCompare".
#pragma once

#include "viewport/render_frame.h"

#include "render/session/render_options.h"
#include "scene/scene.h"
#include "util/result.h"

#include <QImage>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace wavelit::editor {

class CompareSideRender;

class LightMixCompare : public QWidget {
    Q_OBJECT
public:
    struct Side {
        QString label;
        scene::LightingSetup lighting;
        std::function<scene::LightingSetup()> live = {}; // set: the lighting now (the open setup)
    };
    enum class Mode { Remix, Render };
    // What a render side renders with: the viewport's options for a scene, its samples-per-pixel
    // limit (0: progressive forever) and the file relative asset paths start from.
    struct RenderContext {
        std::function<render::RenderOptions(const scene::Scene&)> options;
        int maxSamplesPerPixel = 0;
        std::string scenePath;
    };

    explicit LightMixCompare(QWidget* viewport);
    ~LightMixCompare() override;

    void snapshot(const QString& name, const scene::LightingSetup& lighting);
    std::optional<scene::LightingSetup> snapshotNamed(const QString& name) const;
    QStringList snapshotNames() const;

    // Shows the split view. `rendered`: the scene the viewport renders now (the frame's
    // layersScene, or remixBaseScene of the open scene before the first frame): each side's mode
    // is chosen against it at once (modes()), and again against each frame's. stop() hides the
    // view and stops the side renders.
    void start(Side a, Side b, const scene::Scene& rendered, RenderContext context);
    void stop();
    bool active() const { return m_active; }
    std::array<Mode, 2> modes() const { return {m_sides[0].mode, m_sides[1].mode}; }
    // The wipe line's position, 0 (all B) to 1 (all A), default 0.5.
    void setWipe(double fraction);
    double wipe() const { return m_wipe; }

    // Recomposes from the frame's layers (render sides keep their latest own frame); returns the
    // reason when a side cannot be shown.
    util::Status showFrame(const RenderFrame& frame);
    // The latest frame as shown (tone-mapped; A left of the wipe; null until both sides have an
    // image), each side's mean luminance over the whole image, its linear image and its samples
    // per pixel (a remix: the viewport's; a render: its own).
    QImage composite() const;
    std::array<double, 2> sideMeans() const { return {m_sides[0].mean, m_sides[1].mean}; }
    std::shared_ptr<const util::ImageRGB> sideImage(int side) const { return m_sides[size_t(side)].linear; }
    int sideSamples(int side) const { return m_sides[size_t(side)].samples; }
    // Vulkan validation messages of the side renders so far (tests require 0).
    int sideValidationMessages() const;

signals:
    // A side render failed (its message names the problem); the side shows nothing more.
    void sideRenderFailed(const QString& message);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    struct SideState {
        Side side;
        Mode mode = Mode::Remix;
        CompareSideRender* render = nullptr; // runs while mode is Render
        std::shared_ptr<const util::ImageRGB> linear;
        QImage image; // linear tone-mapped
        double mean = 0.0;
        int samples = 0;
    };
    scene::LightingSetup lightingOf(const SideState& side) const;
    // Chooses the side's mode against `rendered`; for a remix returns its weights, for a render
    // (re)starts its session when the scene it needs changed.
    std::optional<std::vector<glm::vec3>> choose(SideState& side, const scene::Scene& rendered);
    void setLinear(SideState& side, std::shared_ptr<const util::ImageRGB> linear, int samples);
    void onSideRenderFrame(size_t s);
    QRect imageRect() const;
    void wipeTo(int x);

    std::map<QString, scene::LightingSetup> m_snapshots;
    std::array<SideState, 2> m_sides;
    RenderContext m_context;
    bool m_active = false;
    double m_wipe = 0.5;
    float m_exposureEv = 0.0f;
};

const char* compareModeName(LightMixCompare::Mode mode); // "remix" or "render"

// The scene side `lighting` shows over `rendered`: the rendered scene with that lighting, its
// environment map taken as the rendered one when both name the same file (a *.wllight on disk
// names it from its own folder). Exposed for tests.
scene::Scene compareSideScene(const scene::Scene& rendered, const scene::LightingSetup& lighting);

} // namespace wavelit::editor
